#pragma once
// Which of the SIMD targets Google Highway compiles a kernel for this CPU can run, best first.
//
// The kernels (shade_bytes_simd.cpp, small_triangle_simd.cpp, small_triangle_batch_simd.cpp)
// include Highway's headers only: its HWY_DYNAMIC_DISPATCH would need libhwy, whose start-up code
// runs an instruction (rdtscp) that valgrind cannot execute, and callgrind's instruction counts are
// how this project measures the fill. So the choice is made here, from the CPU features each target
// is compiled with (hwy/ops/set_macros-inl.h), by the compiler's __builtin_cpu_supports.
#include <vector>

namespace scantrace {

// One compiled kernel: its Highway target and entry point.
template <class F>
struct SimdKernelOf {
  const char* target;
  F function;
};

// What the CPU supports of the x86 targets, each needing the previous one's features and more.
struct SimdCpu {
  bool ssse3 = false, sse4 = false, avx2 = false, avx3 = false;
};
SimdCpu simd_cpu();

// The kernels this CPU can run, best first, from one kernel's entry point per target as Highway's
// HWY_CHOOSE_<TARGET>(name) gives them (null where the target was not compiled) and its portable
// fallback, HWY_CHOOSE_FALLBACK(name), which runs everywhere.
template <class F>
std::vector<SimdKernelOf<F>> runnable_kernels(F avx3, F avx2, F sse4, F ssse3, F neon, F fallback) {
  const SimdCpu cpu = simd_cpu();
  std::vector<SimdKernelOf<F>> k;
  if (avx3 && cpu.avx3) k.push_back({"AVX3 (AVX-512)", avx3});
  if (avx2 && cpu.avx2) k.push_back({"AVX2", avx2});
  if (sse4 && cpu.sse4) k.push_back({"SSE4", sse4});
  if (ssse3 && cpu.ssse3) k.push_back({"SSSE3", ssse3});
  if (neon) k.push_back({"NEON", neon});  // every AArch64 CPU has it
  k.push_back({"portable", fallback});
  return k;
}

// runnable_kernels's arguments for the kernel `name` compiled for each target by Highway's
// foreach_target, written once for every kernel. Expanded in the kernel's file, which includes
// hwy/highway.h, where HWY_CHOOSE_<TARGET> is defined.
#define SCANTRACE_KERNEL_TARGETS(name)                                                         \
  HWY_CHOOSE_AVX3(name), HWY_CHOOSE_AVX2(name), HWY_CHOOSE_SSE4(name), HWY_CHOOSE_SSSE3(name), \
      HWY_CHOOSE_NEON(name), HWY_CHOOSE_FALLBACK(name)

}  // namespace scantrace
