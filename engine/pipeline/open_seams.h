#pragma once
/// @file open_seams.h
/// @brief Seams that carry no plane (docs/design/block_engine.md, section 4): a block face shared
/// by two blocks on which no detected plane lies. Surface on such a face is not a detected surface
/// but the partition closing a solid where the support regions end; the energy prices it and the
/// run reports how much of the surface lies there.

#include "engine/core/polygon_mesh.h"
#include "partition/arrangement/block_complexes.h"

#include <cstddef>
#include <span>

namespace linesurf::pipeline {

struct BlockFacetRef;

/// True when an input plane lies exactly on seam face `seam` (recorded by either block).
[[nodiscard]] bool SeamCarriesPlane(const partition::BlockComplexes& complexes, std::size_t seam);

struct OpenSeamSurface {
  std::size_t faces = 0;    ///< output faces on seams without a plane
  double area = 0.0;        ///< their area
  double total_area = 0.0;  ///< area of the whole mesh
};

/// The part of `mesh` (faces from `face_facet`, as ExtractBlockSurface gives them) on seams
/// without a plane.
[[nodiscard]] OpenSeamSurface MeasureOpenSeamSurface(const partition::BlockComplexes& complexes,
                                                     const PolygonMesh& mesh,
                                                     std::span<const BlockFacetRef> face_facet);

}  // namespace linesurf::pipeline
