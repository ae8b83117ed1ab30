#pragma once
// The generators of hostile cases, one per kind (one file each).

#include "tests/robustness/hostile_case.h"

#include <vector>

namespace linesurf::robustness {

std::vector<HostileCase> OutputPathCases();
std::vector<HostileCase> InputCases();
std::vector<HostileCase> OptionCases();
std::vector<HostileCase> SignalCases();

/// Every case of every kind.
std::vector<HostileCase> AllHostileCases();

}  // namespace linesurf::robustness
