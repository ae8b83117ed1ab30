// The Cbc backend of a build without Cbc (LINESURF_WITH_CBC off or coinor-libcbc-dev missing).
#include "engine/core/exception.h"
#include "solver/lp/backends/cbc/cbc_backend.h"

namespace linesurf::solver {

bool CbcAvailable() noexcept { return false; }

LpSolution SolveIlpWithCbc(
    const LpModel&, std::size_t, std::span<const double>, const IlpLimits&, const RunContext&) {
  ThrowError(ErrorCode::kInvalidOptions,
             "solve_labeling",
             "this build has no Cbc backend (install coinor-libcbc-dev and reconfigure with "
             "LINESURF_WITH_CBC=ON)");
}

}  // namespace linesurf::solver
