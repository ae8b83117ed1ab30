#pragma once
/// @file judge_result.h
/// @brief Whether a finished reconstruction is what the user asked for: never a silent
/// wrong result. Warnings for results that are usable but suspect, an error for results
/// that are not (docs/user/errors.md lists every message).

#include "linesurf/error.h"

#include "engine/pipeline/decide_scene_mode.h"
#include "engine/pipeline/mesh_topology.h"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace linesurf::pipeline {

/// What the pipeline knows at the end of a run.
struct ResultFacts {
  bool auto_mode = true;  ///< --scene auto (else the mode was given)
  bool interior = false;  ///< the mode used
  SceneModeDecision decision;
  std::size_t planes = 0;
  std::size_t planes_in_complex = 0;
  std::string plane_cap_warning;   ///< PlaneCapWarning of the detection ("" if not capped)
  double detection_epsilon = 0.0;  ///< eps used by plane detection (0: given planes)
  std::size_t cells = 0;
  std::size_t full_cells = 0;
  std::size_t observing_viewpoints = 0;
  std::size_t viewpoints_dropped = 0;        ///< by sanitation (non-finite or beyond the bound)
  std::size_t viewpoints_in_full_cells = 0;  ///< observing viewpoints whose cell is full
  bool has_data_weight = true;               ///< some primitive, visibility or prior weight is > 0
  double sigma = 0.0;
  double scene_diagonal = 0.0;  ///< of the box, local units
  std::size_t samples = 0;
  std::size_t grazing_samples = 0;  ///< samples skipped, viewpoint in the segment's plane
  MeshTopology topology;
  std::size_t mesh_faces = 0;
  /// Blocks engine: surface area on seams that carry no plane (open_seams.h), and the mesh's.
  double open_seam_area = 0.0;
  double mesh_area = 0.0;
  std::size_t open_seam_faces = 0;
};

struct ResultJudgement {
  std::vector<std::string> warnings;
  /// Set when the result is unusable (kDegenerate): an empty or inverted surface.
  std::optional<Error> error;
};

/// Deterministic; O(1).
[[nodiscard]] ResultJudgement JudgeResult(const ResultFacts& facts);

}  // namespace linesurf::pipeline
