#pragma once
// Typed errors of the engine. Library code throws these; only main() turns them into one line on
// stderr and an exit code. Nothing below main() calls exit().
//
//   InputError    — the user's input is at fault (a file, a key, a value, a command-line word):
//                   exit code 1. The message names the file / key / value.
//   InternalError — a broken invariant inside the engine: exit code 2.
#include <stdexcept>
#include <string>

namespace mixengine {

class InputError : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

class InternalError : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

}  // namespace mixengine
