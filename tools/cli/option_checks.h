#pragma once
// Bounds of command-line values, with messages that print numbers as %g (CLI11's own range
// validators print the largest double with 309 digits). Each library options struct checks its
// full range in Validate(); these catch what must not even reach it.

#include <CLI/CLI.hpp>

namespace linesurf::cli {

/// Values >= lo / > lo / in [lo, hi], as numbers.
CLI::Validator AtLeast(double lo);
CLI::Validator Above(double lo);
CLI::Validator Between(double lo, double hi);

/// Adds, to every option of `root` and its subcommands, the check its type needs: unsigned
/// options refuse negatives (CLI11 would wrap -1 to 2^64 - 1), floating-point options refuse
/// nan and inf. Call once, after every subcommand is registered.
void AddTypeChecks(CLI::App& root);

}  // namespace linesurf::cli
