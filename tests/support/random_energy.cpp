#include "tests/support/random_energy.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "engine/core/rng.h"

namespace linesurf::solver::testing {
namespace {

// Picks `k` distinct cells.
std::vector<CellId> DistinctCells(Rng& rng, std::size_t num_cells, std::size_t k) {
  std::vector<CellId> cells;
  while (cells.size() < k) {
    const CellId c(static_cast<std::size_t>(rng.Below(num_cells)));
    if (std::find(cells.begin(), cells.end(), c) == cells.end()) cells.push_back(c);
  }
  return cells;
}

}  // namespace

EnergyInput RandomEnergy(const RandomEnergySpec& spec) {
  Rng rng(MixSeed(spec.seed, RngStage::kSynth, 0x501));
  EnergyInput e;
  const std::size_t n = std::max<std::size_t>(spec.num_cells, 8);
  for (std::size_t c = 0; c < n; ++c) {
    CellFix fix = CellFix::kFree;
    if (rng.Uniform() < spec.fixed_fraction) fix = rng.Uniform() < 0.5 ? CellFix::kEmpty : CellFix::kFull;
    const double empty_cost = rng.Uniform() < 0.5 ? rng.Uniform() : 0.0;
    const double full_cost = rng.Uniform() < 0.5 ? rng.Uniform() : 0.0;
    e.AddCell(empty_cost, full_cost, fix);
  }
  for (std::size_t p = 0; p < spec.num_pairs; ++p) {
    const auto cells = DistinctCells(rng, n, 2);
    e.AddPair(cells[0], cells[1], rng.Uniform(0.1, 1.0));
  }
  for (std::size_t g = 0; g < spec.num_structural; ++g) {
    const auto cells = DistinctCells(rng, n, 2 + rng.Below(3));
    e.AddStructuralGroup(cells, rng.Uniform(0.1, 1.0));
  }
  for (std::size_t g = 0; g < spec.num_parity; ++g) {
    const std::size_t size = rng.Uniform() < 0.7 ? 4 : 8;
    const auto cells = DistinctCells(rng, n, size);
    std::vector<std::int8_t> signs(size);
    for (std::size_t i = 0; i < size; ++i) signs[i] = i % 2 == 0 ? 1 : -1;
    const double weight = rng.Uniform(0.1, 1.0);
    const auto constant =
        static_cast<std::int8_t>(spec.parity_constants ? static_cast<int>(rng.Below(3)) - 1 : 0);
    e.AddParityGroup(cells, signs, weight, constant);
  }
  return e;
}

EnergyInput SmallRandomEnergy(std::uint64_t seed, bool parity_constants) {
  RandomEnergySpec spec;
  spec.parity_constants = parity_constants;
  spec.num_cells = 30;
  spec.num_pairs = 50;
  spec.num_structural = 8;
  spec.num_parity = 10;
  spec.seed = seed;
  return RandomEnergy(spec);
}

EnergyInput GridEnergy(const GridEnergySpec& spec) {
  Rng rng(MixSeed(spec.seed, RngStage::kSynth, 0x6e1d));
  const int nx = spec.nx, ny = spec.ny, nz = spec.nz;
  auto id = [&](int i, int j, int k) {
    return CellId(static_cast<std::size_t>((k * ny + j) * nx + i));
  };
  // Three balls well inside the grid.
  struct Ball {
    double x, y, z, r;
  };
  std::vector<Ball> balls;
  const double extent = std::min({nx, ny, nz});
  for (int b = 0; b < 3; ++b) {
    const double r = rng.Uniform(0.15, 0.3) * extent;
    balls.push_back({rng.Uniform(r + 1, nx - r - 1), rng.Uniform(r + 1, ny - r - 1),
                     rng.Uniform(r + 1, nz - r - 1), r});
  }
  // Signed distance (negative inside) to the union of balls, at a cell centre.
  auto distance = [&](int i, int j, int k) {
    double d = 1e300;
    for (const Ball& b : balls) {
      d = std::min(d, std::hypot(i + 0.5 - b.x, j + 0.5 - b.y, k + 0.5 - b.z) - b.r);
    }
    return d;
  };
  EnergyInput e;
  e.ResizeCells(static_cast<std::size_t>(nx) * ny * nz);
  for (int k = 0; k < nz; ++k) {
    for (int j = 0; j < ny; ++j) {
      for (int i = 0; i < nx; ++i) {
        const CellId c = id(i, j, k);
        const double d = distance(i, j, k);
        if (i == 0 || j == 0 || k == 0 || i == nx - 1 || j == ny - 1 || k == nz - 1) {
          e.fixed[c] = CellFix::kEmpty;
        }
        // Textural evidence on the inner shell, with dropout; outliers elsewhere.
        if (d < 0.0 && d > -1.0 && rng.Uniform() < 0.7) e.cost_if_empty[c] = rng.Uniform(0.5, 1.5);
        if (rng.Uniform() < 0.01) e.cost_if_empty[c] += rng.Uniform(0.0, 1.0);
        // Viewpoint prior on a few outside cells.
        if (d > 2.0 && rng.Uniform() < 0.002) e.cost_if_full[c] = 1.0;
      }
    }
  }
  // Pairs: visibility outside (and a little noise across the surface), plus a tiny area term.
  const double area_weight = 0.1 * spec.edge_weight;
  for (int k = 0; k < nz; ++k) {
    for (int j = 0; j < ny; ++j) {
      for (int i = 0; i < nx; ++i) {
        const int nb[3][3] = {{i + 1, j, k}, {i, j + 1, k}, {i, j, k + 1}};
        for (const auto& q : nb) {
          if (q[0] >= nx || q[1] >= ny || q[2] >= nz) continue;
          const double d = std::min(distance(i, j, k), distance(q[0], q[1], q[2]));
          double w = area_weight;
          if (d > 0.0 && rng.Uniform() < 0.6) w += spec.visibility_weight * rng.Uniform(0.0, 3.0);
          if (d <= 0.0 && rng.Uniform() < 0.05) w += spec.visibility_weight * rng.Uniform(0.0, 1.0);
          e.AddPair(id(i, j, k), id(q[0], q[1], q[2]), w);
        }
      }
    }
  }
  // Structural groups: 3 cells along an axis near the surface.
  for (int k = 1; k + 3 < nz; ++k) {
    for (int j = 1; j + 3 < ny; ++j) {
      for (int i = 1; i + 3 < nx; ++i) {
        const double d = distance(i, j, k);
        if (std::abs(d) > 1.5 || rng.Uniform() > 0.3) continue;
        const int axis = static_cast<int>(rng.Below(3));
        CellId cells[3];
        for (int s = 0; s < 3; ++s) {
          cells[s] = id(i + (axis == 0 ? s : 0), j + (axis == 1 ? s : 0), k + (axis == 2 ? s : 0));
        }
        e.AddStructuralGroup(cells, spec.structural_weight * rng.Uniform(0.1, 1.0));
      }
    }
  }
  // Parity groups: the 4 cells around each interior grid edge, nu = (-1)^(i+j+k).
  if (spec.edge_weight > 0.0) {
    auto sign = [](int i, int j, int k) -> std::int8_t { return (i + j + k) % 2 == 0 ? 1 : -1; };
    for (int k = 0; k + 1 < nz; ++k) {
      for (int j = 0; j + 1 < ny; ++j) {
        for (int i = 0; i + 1 < nx; ++i) {
          const int around[3][4][3] = {
              {{i, j, k}, {i, j + 1, k}, {i, j + 1, k + 1}, {i, j, k + 1}},   // edge along x
              {{i, j, k}, {i + 1, j, k}, {i + 1, j, k + 1}, {i, j, k + 1}},   // edge along y
              {{i, j, k}, {i + 1, j, k}, {i + 1, j + 1, k}, {i, j + 1, k}}};  // edge along z
          for (const auto& group : around) {
            CellId cells[4];
            std::int8_t signs[4];
            for (int s = 0; s < 4; ++s) {
              cells[s] = id(group[s][0], group[s][1], group[s][2]);
              signs[s] = sign(group[s][0], group[s][1], group[s][2]);
            }
            e.AddParityGroup(cells, signs, spec.edge_weight);
          }
        }
      }
    }
  }
  return e;
}

double BruteForceMinimum(const EnergyInput& e) {
  const std::vector<CellId> free = e.FreeCells();
  if (free.size() > 20) return std::nan("");
  double best = INFINITY;
  std::vector<std::uint8_t> labels(e.NumCells());
  for (std::uint32_t mask = 0; mask < (1u << free.size()); ++mask) {
    for (std::size_t c = 0; c < e.NumCells(); ++c) {
      labels[c] = e.fixed[CellId(c)] == CellFix::kFull ? 1 : 0;
    }
    for (std::size_t j = 0; j < free.size(); ++j) labels[free[j].index()] = (mask >> j) & 1u;
    best = std::min(best, e.Evaluate(std::span<const std::uint8_t>(labels)));
  }
  return best;
}

std::vector<std::uint32_t> GridBlocks(const GridEnergySpec& spec, int block_size) {
  const auto blocks_along = [&](int n) {
    return static_cast<std::uint32_t>((n + block_size - 1) / block_size);
  };
  const std::uint32_t bx = blocks_along(spec.nx), by = blocks_along(spec.ny);
  std::vector<std::uint32_t> block_of_cell;
  for (int k = 0; k < spec.nz; ++k) {
    for (int j = 0; j < spec.ny; ++j) {
      for (int i = 0; i < spec.nx; ++i) {
        const std::uint32_t b[3] = {static_cast<std::uint32_t>(i / block_size),
                                    static_cast<std::uint32_t>(j / block_size),
                                    static_cast<std::uint32_t>(k / block_size)};
        block_of_cell.push_back((b[2] * by + b[1]) * bx + b[0]);
      }
    }
  }
  return block_of_cell;
}

}  // namespace linesurf::solver::testing
