// pendepth 3D viewer: draws the scene JSON that src/io/html3.cpp writes into the page, with
// three.js (r147: the UMD build and the classic OrbitControls, inlined by the build).
//
// Scene: {title, layers: [{id, label, color, visible}], meshes: [{layer, color, opacity,
// vertices: [x,y,z,…], triangles: [a,b,c,…], highlight: {color, triangles, edges, vertices}}],
// points: [{layer, color, label, at}], arrows: [{layer, color, label, from, to}],
// numbers: [[label, text], …], notes: [text, …]}.
// Coordinates arrive normalised (scene centre at 0, largest half-extent in [0.5, 1]) so float32
// buffers work at any input scale; sizes of markers below are in those units. The panel's
// numbers are the exact doubles as text. Rendering is on demand (no animation loop).
(function () {
  'use strict';
  const data = JSON.parse(document.getElementById('pendepth-scene').textContent);

  const MARKER = 0.018;     // radius of a point marker
  const EDGE = 0.006;       // radius of a highlighted edge
  const SHAFT = 0.008;      // radius of an arrow's shaft (at most a tenth of its length)

  // ---- the panel ----
  document.getElementById('title').textContent = data.title || 'pendepth';
  document.title = data.title || document.title;
  const numbers = document.getElementById('numbers');
  for (const [label, text] of data.numbers || []) {
    const row = numbers.insertRow();
    row.insertCell().textContent = label;
    row.insertCell().textContent = text;
  }
  document.getElementById('notes').textContent = (data.notes || []).join(' ');

  // ---- three.js scene ----
  const container = document.getElementById('view');
  const renderer = new THREE.WebGLRenderer({antialias: true, preserveDrawingBuffer: true});
  renderer.setPixelRatio(window.devicePixelRatio || 1);
  renderer.setSize(container.clientWidth, container.clientHeight);
  renderer.setClearColor(0xf3f4f6);
  container.appendChild(renderer.domElement);

  const scene = new THREE.Scene();
  const camera = new THREE.PerspectiveCamera(35, container.clientWidth / container.clientHeight, 0.01, 100);
  camera.up.set(0, 0, 1);  // z up, as in most CAD and robotics data
  camera.add(new THREE.DirectionalLight(0xffffff, 0.75));
  scene.add(camera);
  scene.add(new THREE.AmbientLight(0xffffff, 0.45));

  // Layers hidden at first can be shown from the address: page.html#show=M,direction
  const shown = (new URLSearchParams(location.hash.slice(1)).get('show') || '').split(',');
  const layers = {};
  for (const layer of data.layers || []) {
    const group = new THREE.Group();
    group.visible = layer.visible !== false || shown.includes(layer.id);
    scene.add(group);
    layers[layer.id] = group;
  }
  const layerOf = (id) => layers[id] || scene;
  const v3 = (a) => new THREE.Vector3(a[0], a[1], a[2]);

  function triangleGeometry(vertices, triangles, subset) {
    const ids = subset || Array.from({length: triangles.length / 3}, (_, i) => i);
    const pos = new Float32Array(ids.length * 9);
    ids.forEach((t, k) => {
      for (let c = 0; c < 3; ++c) {
        const v = triangles[3 * t + c];
        pos.set(vertices.slice(3 * v, 3 * v + 3), 9 * k + 3 * c);
      }
    });
    const g = new THREE.BufferGeometry();
    g.setAttribute('position', new THREE.BufferAttribute(pos, 3));
    g.computeVertexNormals();  // non-indexed: flat shading
    return g;
  }

  function cylinderBetween(a, b, radius, material) {
    const dir = new THREE.Vector3().subVectors(b, a);
    const length = dir.length();
    const mesh = new THREE.Mesh(new THREE.CylinderGeometry(radius, radius, length, 12), material);
    mesh.position.copy(a).addScaledVector(dir, 0.5);
    mesh.quaternion.setFromUnitVectors(new THREE.Vector3(0, 1, 0), dir.normalize());
    return mesh;
  }

  function addMesh(m) {
    const group = layerOf(m.layer);
    const geometry = triangleGeometry(m.vertices, m.triangles);
    const opaque = (m.opacity === undefined ? 1 : m.opacity) >= 1;
    const material = new THREE.MeshLambertMaterial({
      color: m.color, transparent: !opaque, opacity: m.opacity, depthWrite: opaque,
      side: opaque ? THREE.FrontSide : THREE.DoubleSide,
      polygonOffset: true, polygonOffsetFactor: 1, polygonOffsetUnits: 1});
    group.add(new THREE.Mesh(geometry, material));
    // Outline the true faces only (coplanar triangles share no drawn edge).
    const outline = new THREE.LineSegments(new THREE.EdgesGeometry(geometry, 1),
      new THREE.LineBasicMaterial({color: 0x30363d, transparent: !opaque, opacity: opaque ? 1 : 0.6}));
    group.add(outline);

    const h = m.highlight;
    if (!h) return;
    const hm = new THREE.MeshLambertMaterial({color: h.color, side: THREE.DoubleSide,
      polygonOffset: true, polygonOffsetFactor: -1, polygonOffsetUnits: -1});
    if (h.triangles && h.triangles.length) group.add(new THREE.Mesh(triangleGeometry(m.vertices, m.triangles, h.triangles), hm));
    const at = (v) => new THREE.Vector3(m.vertices[3 * v], m.vertices[3 * v + 1], m.vertices[3 * v + 2]);
    for (let k = 0; h.edges && k + 1 < h.edges.length; k += 2) {
      const a = at(h.edges[k]), b = at(h.edges[k + 1]);
      if (a.distanceTo(b) > 0) group.add(cylinderBetween(a, b, EDGE, hm));
    }
    for (const v of h.vertices || []) {
      const s = new THREE.Mesh(new THREE.SphereGeometry(1.4 * MARKER, 20, 14), hm);
      s.position.copy(at(v));
      group.add(s);
    }
  }

  // Points and arrows are drawn over the shapes (no depth test): a witness inside a solid still shows.
  const overlay = (color) => new THREE.MeshLambertMaterial({color: color, depthTest: false, transparent: true});
  const onTop = (object) => { object.renderOrder = 10; return object; };

  function addPoint(p) {
    const s = onTop(new THREE.Mesh(new THREE.SphereGeometry(MARKER, 20, 14), overlay(p.color)));
    s.position.copy(v3(p.at));
    layerOf(p.layer).add(s);
  }

  // An arrow with a visible shaft and head however short (a zero-length arrow is not drawn).
  function addArrow(a) {
    const from = v3(a.from), to = v3(a.to);
    const length = from.distanceTo(to);
    if (!(length > 0)) return;
    const material = overlay(a.color);
    const head = Math.min(0.09, 0.35 * length);
    const radius = Math.min(SHAFT, length / 10);
    const dir = new THREE.Vector3().subVectors(to, from).normalize();
    const neck = to.clone().addScaledVector(dir, -head);
    const group = layerOf(a.layer);
    if (neck.distanceTo(from) > 0) group.add(onTop(cylinderBetween(from, neck, radius, material)));
    const cone = onTop(new THREE.Mesh(new THREE.ConeGeometry(Math.max(2.5 * radius, head / 3), head, 20), material));
    cone.position.copy(neck).addScaledVector(dir, head / 2);
    cone.quaternion.setFromUnitVectors(new THREE.Vector3(0, 1, 0), dir);
    group.add(cone);
  }

  (data.meshes || []).forEach(addMesh);
  (data.points || []).forEach(addPoint);
  (data.arrows || []).forEach(addArrow);

  // ---- view: orbit / pan / zoom, automatic framing of the visible layers ----
  const controls = new THREE.OrbitControls(camera, renderer.domElement);
  const render = () => renderer.render(scene, camera);
  controls.addEventListener('change', render);

  function fit(keepDirection) {
    const box = new THREE.Box3();
    for (const id in layers) if (layers[id].visible) box.expandByObject(layers[id]);
    if (box.isEmpty()) box.set(new THREE.Vector3(-1, -1, -1), new THREE.Vector3(1, 1, 1));
    const sphere = box.getBoundingSphere(new THREE.Sphere());
    const radius = Math.max(sphere.radius, 1e-3);
    const distance = 1.15 * radius / Math.sin(THREE.MathUtils.degToRad(camera.fov / 2));
    const dir = keepDirection ? new THREE.Vector3().subVectors(camera.position, controls.target).normalize()
                              : new THREE.Vector3(1.0, -1.6, 0.9).normalize();
    controls.target.copy(sphere.center);
    camera.position.copy(sphere.center).addScaledVector(dir, distance);
    camera.near = distance / 100;
    camera.far = distance * 100;
    camera.updateProjectionMatrix();
    controls.update();
    render();
  }

  const layerList = document.getElementById('layers');
  for (const layer of data.layers || []) {
    const label = document.createElement('label');
    const box = document.createElement('input');
    box.type = 'checkbox';
    box.checked = layers[layer.id].visible;
    box.addEventListener('change', () => {
      layers[layer.id].visible = box.checked;
      fit(true);
    });
    const swatch = document.createElement('span');
    swatch.className = 'swatch';
    swatch.style.background = layer.color || '#888';
    label.append(box, swatch, layer.label);
    layerList.appendChild(label);
  }
  document.getElementById('reset').addEventListener('click', () => fit(false));
  window.addEventListener('resize', () => {
    camera.aspect = container.clientWidth / container.clientHeight;
    camera.updateProjectionMatrix();
    renderer.setSize(container.clientWidth, container.clientHeight);
    render();
  });

  fit(false);
  if (document.body.dataset.pendepthStatus === 'loading') document.body.dataset.pendepthStatus = 'ok';
})();
