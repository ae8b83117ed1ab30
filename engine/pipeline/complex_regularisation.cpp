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
    // Vertex -> incident edges (counting sort, edges ascending per vertex).
    std::vector<std::uint32_t> offsets(cx.NumVertices() + 1, 0);
    for (std::size_t e = 0; e < cx.NumEdges(); ++e) {
      for (const VertexId v : cx.edge_vertices[EdgeId(e)]) ++offsets[v.index() + 1];
    }
    for (std::size_t v = 0; v < cx.NumVertices(); ++v) offsets[v + 1] += offsets[v];
    std::vector<std::uint32_t> incident(offsets.back());
    std::vector<std::uint32_t> fill(offsets.begin(), offsets.end() - 1);
    for (std::size_t e = 0; e < cx.NumEdges(); ++e) {
      for (const VertexId v : cx.edge_vertices[EdgeId(e)]) {
        incident[fill[v.index()]++] = static_cast<std::uint32_t>(e);
      }
    }
    for (std::size_t v = 0; v < cx.NumVertices(); ++v) {
      bool interior = offsets[v + 1] > offsets[v];
      cells.clear();
      for (std::uint32_t i = offsets[v]; i < offsets[v + 1] && interior; ++i) {
        interior = edge_interior[incident[i]] != 0;
        const auto around = cx.edge_cells[EdgeId(static_cast<std::size_t>(incident[i]))];
        cells.insert(cells.end(), around.begin(), around.end());
      }
      if (!interior) continue;
      add_group(options.weights.corner);
    }
  }
}

}  // namespace linesurf::pipeline
