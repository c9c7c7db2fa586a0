// Private: shapes made from meshes (src/front/shape3_mesh.cpp).
#pragma once

#include <pendepth/pendepth.hpp>

namespace pendepth::front {

/// `s` itself if it is convex; else throws InvalidInput "mesh queries are not implemented yet:
/// WHICH (NAME) is not convex (use the hull: Shape3::from_file(path, name, true) / --hull)".
Shape3 convex_only(Shape3 s, const char* which);

}  // namespace pendepth::front
