#pragma once
// What a user waits for: a command run as a new process, start-up and all. The bench times
// `scantrace render` this way, because a warm render inside one process hides the dynamic
// linking, the scene's parsing, the first touch of the image's memory and the PNG encoding.
#include <string>
#include <vector>

namespace scantrace::bench {

// Runs `argv` (argv[0] a path, no shell) with stdout and stderr sent to /dev/null, waits for it
// and returns the wall time in seconds. Throws std::runtime_error, naming the command, when it
// cannot start or exits with a non-zero status.
double run_child_seconds(const std::vector<std::string>& argv);

}  // namespace scantrace::bench
