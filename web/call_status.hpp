#pragma once
// How a module's exported C function reports to JavaScript (the full module's bindings.hpp, the
// trace page's web/player/player_module.cpp): 0 done, 1 bad input (`error` is the CLI's one-line
// message), 2 a bad argument from the JavaScript side (std::invalid_argument).
#include <exception>
#include <new>
#include <stdexcept>
#include <string>

#include "io/input_error.hpp"

namespace scantrace::web {

template <class Work>
int call_status(Work&& work, std::string& error) {
  try {
    work();
    return 0;
  } catch (const InputError& e) {
    error = e.what();
    return 1;
  } catch (const std::invalid_argument& e) {
    error = e.what();
    return 2;
  } catch (const std::bad_alloc&) {
    error = "out of memory";
    return 1;
  } catch (const std::exception& e) {
    error = e.what();
    return 1;
  }
}

}  // namespace scantrace::web
