// The one exception hierarchy of medusa's libraries (docs/CONVENTIONS.md). The CLI turns each kind
// into one line on stderr and the exit code documented in the README.
#pragma once

#include <stdexcept>
#include <string>

namespace medusa {

// Base of every exception thrown by medusa's libraries.
class Error : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

// Bad user input: a malformed file, an invalid value, an inconsistent run.
class InputError : public Error {
public:
  using Error::Error;
};

// The input is valid but its geometry is outside what the method handles (coplanar 3D data, fewer
// than four cells, colliding trajectories; docs/MATH.md §2.5 and §5.7).
class GeometryError : public Error {
public:
  using Error::Error;
};

// Reading or writing a store failed (I/O error, corrupt or truncated file).
class StoreError : public Error {
public:
  using Error::Error;
};

// An internal invariant was violated (a failed audit). Always a bug in medusa.
class InternalError : public Error {
public:
  using Error::Error;
};

} // namespace medusa
