#pragma once
// Counts the calls of the global operator new made by this thread, so that `scantrace bench` can
// show that a warm render allocates a fixed handful of buffers, not one per triangle or per row.
// The replacement (allocation_counter.cpp) forwards to malloc and adds one thread-local increment.
namespace scantrace::bench {

long long allocations_so_far();

}  // namespace scantrace::bench
