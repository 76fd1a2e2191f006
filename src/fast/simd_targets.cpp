#include "simd_targets.hpp"

#include <algorithm>
#include <initializer_list>
#if defined(__x86_64__) || defined(__i386__)
#include <cpuid.h>
#endif

namespace scantrace {

#if defined(__x86_64__) || defined(__i386__)
namespace {

// F16C from CPUID leaf 1 (clang's __builtin_cpu_supports does not know the name).
int has_f16c() {
  unsigned a = 0, b = 0, c = 0, d = 0;
  return __get_cpuid(1, &a, &b, &c, &d) && (c & bit_F16C) != 0;
}

// Whether every __builtin_cpu_supports(...) given is nonzero (it takes only string literals).
bool has(std::initializer_list<int> features) {
  return std::all_of(features.begin(), features.end(), [](int f) { return f != 0; });
}

}  // namespace
#endif

SimdCpu simd_cpu() {
  SimdCpu cpu;
#if defined(__x86_64__) || defined(__i386__)
  cpu.ssse3 = __builtin_cpu_supports("ssse3");
  cpu.sse4 = cpu.ssse3 && has({__builtin_cpu_supports("sse4.1"), __builtin_cpu_supports("sse4.2"),
                               __builtin_cpu_supports("pclmul"), __builtin_cpu_supports("aes")});
  cpu.avx2 = cpu.sse4 && has({__builtin_cpu_supports("avx"), __builtin_cpu_supports("avx2"),
                              __builtin_cpu_supports("bmi"), __builtin_cpu_supports("bmi2"),
                              __builtin_cpu_supports("fma"), has_f16c()});
  cpu.avx3 =
      cpu.avx2 && has({__builtin_cpu_supports("avx512f"), __builtin_cpu_supports("avx512vl"),
                       __builtin_cpu_supports("avx512dq"), __builtin_cpu_supports("avx512bw")});
#endif
  return cpu;
}

}  // namespace scantrace
