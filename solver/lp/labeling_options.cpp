#include "solver/lp/labeling_options.h"

#include "solver/lp/labeling_backends.h"

#include <cmath>
#include <string>

namespace linesurf::solver {
namespace {

Error InvalidLabelingOption(const std::string& message) {
  return Error{ErrorCode::kInvalidOptions, "solve_labeling", message};
}

using BackendFilter = bool (*)(const LabelingBackend&);

bool AnyBackend(const LabelingBackend& /*backend*/) { return true; }
bool PerBlockBackend(const LabelingBackend& backend) { return backend.capabilities.per_block; }

// `field` names a backend of the table for which `keep` holds and that this build has.
Status CheckBackend(const char* field, SolverBackend backend, BackendFilter keep) {
  const LabelingBackend* entry = FindBackend(backend);
  if (entry == nullptr || !keep(*entry)) {
    std::string message = field;
    if (entry == nullptr) {
      message += ": value ";
      message += std::to_string(static_cast<int>(backend));
    } else {
      message += ": '";
      message += SolverBackendName(backend);
      message += "'";
    }
    message += " is not one of ";
    message += BackendNames(keep);
    return InvalidLabelingOption(message);
  }
  if (!entry->availability.in_this_build()) {
    std::string message = field;
    message += ": '";
    message += SolverBackendName(backend);
    message += "' is not in this build (";
    message += entry->availability.missing_hint;
    message += ")";
    return InvalidLabelingOption(message);
  }
  return {};
}

}  // namespace

Status ClpOptions::Validate() const {
  if (!(tolerance > 0.0 && tolerance <= 1e-2)) {
    return InvalidLabelingOption("clp_tolerance: must be in (0, 1e-2]");
  }
  return {};
}

Status PdhgOptions::Validate() const {
  if (!(tolerance > 0.0 && tolerance <= 1e-1)) {
    return InvalidLabelingOption("pdhg_tolerance: must be in (0, 1e-1]");
  }
  if (max_iterations < 1) return InvalidLabelingOption("pdhg_max_iterations: must be >= 1");
  return {};
}

Status PdhgEnergyOptions::Validate() const {
  if (!(tolerance > 0.0 && tolerance <= 1e-1)) {
    return InvalidLabelingOption("pdhg_energy_tolerance: must be in (0, 1e-1]");
  }
  if (max_iterations < 1) {
    return InvalidLabelingOption("pdhg_energy_max_iterations: must be >= 1");
  }
  return {};
}

Status BandOptions::Validate() const {
  if (rings < 0 || rings > 16) return InvalidLabelingOption("band_rings: must be in [0, 16]");
  return {};
}

Status BlocksOptions::Validate() const {
  if (Status s = CheckBackend("block_backend", backend, PerBlockBackend); !s) return s;
  if (sweeps < 0 || sweeps > 100) return InvalidLabelingOption("block_sweeps: must be in [0, 100]");
  if (halo < 0 || halo > 8) return InvalidLabelingOption("block_halo: must be in [0, 8]");
  if (bound_passes < 0 || bound_passes > 10000) {
    return InvalidLabelingOption("block_bound_passes: must be in [0, 10000]");
  }
  return {};
}

Status ImproveOptions::Validate() const {
  if (local_search_passes < 0 || local_search_passes > 1000) {
    return InvalidLabelingOption("local_search_passes: must be in [0, 1000]");
  }
  if (group_move_passes < 0 || group_move_passes > 1000) {
    return InvalidLabelingOption("group_move_passes: must be in [0, 1000]");
  }
  if (window_cells > 4096) return InvalidLabelingOption("window_cells: must be in [0, 4096]");
  if (window_max_nodes < 1) return InvalidLabelingOption("window_max_nodes: must be >= 1");
  return {};
}

Status LabelingOptions::Validate() const {
  if (Status s = CheckBackend("backend", backend, AnyBackend); !s) return s;
  if (Status s = blocks.Validate(); !s) return s;
  if (Status s = band.Validate(); !s) return s;
  if (Status s = clp.Validate(); !s) return s;
  if (Status s = pdhg.Validate(); !s) return s;
  if (Status s = pdhg_energy.Validate(); !s) return s;
  if (Status s = improve.Validate(); !s) return s;
  if (!(time_limit_seconds >= 0.0) || !std::isfinite(time_limit_seconds)) {
    return InvalidLabelingOption("time_limit_seconds: must be finite and >= 0");
  }
  return {};
}

}  // namespace linesurf::solver
