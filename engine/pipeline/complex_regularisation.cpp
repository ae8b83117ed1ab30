#include "engine/pipeline/complex_regularisation.h"

#include <algorithm>
#include <cstdint>
#include <vector>

namespace linesurf::pipeline {

void AddComplexRegularisation(const CellComplex& cx,
                              const EnergyOptions& options,
                              double sigma,
                              std::size_t first_cell,
                              solver::EnergyInput& energy) {
  std::vector<std::uint8_t> edge_interior(cx.NumEdges(), 0);
  for (std::size_t e = 0; e < cx.NumEdges(); ++e) {
    const EdgeId id(e);
    edge_interior[e] = cx.edge_cells[id].size() == cx.edge_facets[id].size() ? 1 : 0;
  }
  std::vector<CellId> cells;
  std::vector<std::int8_t> signs;
  const auto add_group = [&](double weight) {
    std::sort(cells.begin(), cells.end());
    cells.erase(std::unique(cells.begin(), cells.end()), cells.end());
    signs.clear();
    for (CellId& cell : cells) {
      signs.push_back(cx.cell_colour[cell]);
      cell = CellId(first_cell + cell.index());
    }
    energy.AddParityGroup(cells, signs, weight);
  };
  if (options.weights.edge > 0.0) {
    for (std::size_t e = 0; e < cx.NumEdges(); ++e) {
      if (edge_interior[e] == 0) continue;
      const EdgeId id(e);
      const auto& ev = cx.edge_vertices[id];
      const double length = (cx.vertex_points[ev[1]] - cx.vertex_points[ev[0]]).norm();
      const double weight = options.weights.edge * length / sigma;
      if (!(weight > 0.0)) continue;
      const auto around = cx.edge_cells[id];
      cells.assign(around.begin(), around.end());
      add_group(weight);
    }
  }
  if (options.weights.corner > 0.0) {
    // Vertex -> incident edges, edges ascending per vertex (each edge has its two ends).
    const auto incident = Csr<VertexId, EdgeId>::FromPairs(
        cx.NumVertices(),
        2 * cx.NumEdges(),
        [&](std::size_t k) { return cx.edge_vertices[EdgeId(k / 2)][k % 2]; },
        [](std::size_t k) { return EdgeId(k / 2); });
    for (std::size_t v = 0; v < cx.NumVertices(); ++v) {
      const std::span<const EdgeId> edges = incident[VertexId(v)];
      bool interior = !edges.empty();
      cells.clear();
      for (std::size_t i = 0; i < edges.size() && interior; ++i) {
        interior = edge_interior[edges[i].index()] != 0;
        const auto around = cx.edge_cells[edges[i]];
        cells.insert(cells.end(), around.begin(), around.end());
      }
      if (!interior) continue;
      add_group(options.weights.corner);
    }
  }
}

}  // namespace linesurf::pipeline
