// Run-time instruction-set dispatch (isa.hpp): the processor test, once.
#include "geometry/isa.hpp"

#include <cstdlib>
#include <cstring>

namespace pendepth::isa {

bool v3_available() {
#if PENDEPTH_V3_CLONES
  // libgcc's test includes the OS's support of the AVX register state (XGETBV).
  static const bool has = __builtin_cpu_supports("x86-64-v3");
  return has;
#else
  return false;
#endif
}

bool& use_v3() {
  static bool use = [] {
    const char* e = std::getenv("PENDEPTH_ISA");
    return v3_available() && !(e && std::strcmp(e, "baseline") == 0);
  }();
  return use;
}

}  // namespace pendepth::isa
