// Shared by the reader tests (test_mesh_readers.cpp, test_strict_readers.cpp): the message of the
// InvalidInput a reader throws on a text, or "(no error)".
#pragma once

#include <pendepth/io.hpp>

#include <string>
#include <string_view>

namespace io_test {

template <class F>
std::string error_of(F&& f) {
  try {
    f();
  } catch (const pendepth::InvalidInput& e) {
    return e.what();
  }
  return "(no error)";
}

namespace io = pendepth::io;
inline std::string obj_error(std::string_view text) { return error_of([&] { io::parse_obj_points(text, "m.obj"); }); }
inline std::string off_error(std::string_view text) { return error_of([&] { io::parse_off_points(text, "m.off"); }); }
inline std::string stl_error(std::string_view bytes) { return error_of([&] { io::parse_stl_points(bytes, "m.stl"); }); }

}  // namespace io_test
