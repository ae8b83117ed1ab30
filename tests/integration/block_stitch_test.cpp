// The stitch on the synthetic families, without the solver: block
// partitions of synth house, lshape, room, floor, city-4 and city-16 with their true planes, cells
// labelled full when their centroid lies inside the ground truth, stitched into one mesh (block
// facets, and coplanar faces merged) that `linesurf evaluate`'s checks find closed, 2-manifold,
// oriented and not self-intersecting, with no vertex inside another face's edge and the volume of
// the full cells.

#include "engine/pipeline/block_partition.h"
#include "engine/pipeline/extract_block_surface.h"
#include "partition/arrangement/cell_geometry.h"
#include "tests/support/mesh_checks.h"
#include "tests/support/t_junctions.h"
#include "engine/pipeline/mesh_validity.h"
#include "tools/gen/synthesize.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace linesurf {
namespace {

struct Family {
  std::string name;
  int size = 0;
};

class BlockStitch : public ::testing::TestWithParam<Family> {};

TEST_P(BlockStitch, GroundTruthLabelsGiveAClosedConformingManifold) {
  synth::SynthSpec spec;
  spec.family = GetParam().name;
  spec.size = GetParam().size;
  spec.seed = 1;
  const Expected<synth::SyntheticScene> s = synth::Synthesize(spec);
  ASSERT_TRUE(s) << s.error().ToString();
  Box3 box;
  for (const Vec3& p : s->ground_truth.vertices) box.Extend(p);
  for (const Vec3& v : s->scene.viewpoints) box.Extend(v);
  box = Box3{box.min - 0.05 * box.Extent(), box.max + 0.05 * box.Extent()};
  const double longest = box.Extent().maxCoeff();
  std::size_t seam_edges = 0;
  for (const int margin : {0, 1}) {
    for (const double blocks : {3.0, 5.5}) {
      SCOPED_TRACE(std::to_string(margin) + " margin, " + std::to_string(blocks) + " blocks");
      pipeline::BlockPartitionOptions options;
      options.block_size = longest / blocks;
      options.support.margin_blocks = margin;
      const Expected<pipeline::BlockPartition> p =
          pipeline::BuildBlockPartition(s->scene, box, options, RunContext{});
      ASSERT_TRUE(p) << p.error().ToString();
      std::vector<Vec3> centroids;
      std::vector<double> volumes;
      for (const partition::BlockComplex& block : p->complexes.blocks) {
        for (std::size_t c = 0; c < block.complex.NumCells(); ++c) {
          centroids.push_back(partition::CellCentroid(block.complex, CellId(c)));
          volumes.push_back(partition::CellVolume(block.complex, CellId(c)));
        }
      }
      const std::vector<bool> inside = testing::PointsStrictlyInside(s->ground_truth, centroids);
      ASSERT_EQ(inside.size(), centroids.size());
      std::vector<std::uint8_t> labels(centroids.size(), 0);
      double volume = 0.0;
      for (std::size_t c = 0; c < labels.size(); ++c) {
        labels[c] = inside[c] ? 1 : 0;
        volume += inside[c] ? volumes[c] : 0.0;
      }
      ASSERT_GT(volume, 0.0);
      std::size_t faces = 0;
      for (const bool merge : {false, true}) {
        SCOPED_TRACE(merge ? "merged" : "block facets");
        pipeline::ExtractOptions extract;
        extract.merge_coplanar = merge;
        const Expected<pipeline::BlockExtractResult> r =
            pipeline::ExtractBlockSurface(p->complexes, labels, extract, RunContext{});
        ASSERT_TRUE(r) << r.error().ToString();
        const Expected<MeshValidity> t = CheckMeshValidity(r->mesh);
        ASSERT_TRUE(t) << t.error().ToString();
        EXPECT_TRUE(t->closed);
        EXPECT_TRUE(t->two_manifold);
        EXPECT_TRUE(t->oriented);
        EXPECT_FALSE(t->self_intersecting);
        EXPECT_NEAR(t->signed_volume, volume, 1e-9 * volume);
        EXPECT_EQ(testing::CountTJunctions(r->mesh), 0u);
        if (merge) {
          EXPECT_LE(r->mesh.NumFaces(), faces);
        }
        faces = r->mesh.NumFaces();
        seam_edges += r->stitch.edges_on_block_faces;
      }
    }
  }
  EXPECT_GT(seam_edges, 0u) << "the surface crossed no block face";
}

INSTANTIATE_TEST_SUITE_P(Families,
                         BlockStitch,
                         ::testing::Values(Family{"house"},
                                           Family{"lshape"},
                                           Family{"room"},
                                           Family{"floor"},
                                           Family{"city", 4},
                                           Family{"city", 16}),
                         [](const ::testing::TestParamInfo<Family>& info) {
                           return info.param.name + std::to_string(info.param.size);
                         });

}  // namespace
}  // namespace linesurf
