#include "solver/lp/backends/maxflow/maxflow_backend.h"

#include <memory>

#include <maxflow/graph.h>

#include "engine/core/exception.h"

namespace linesurf::solver {
namespace {

constexpr const char* kMaxflowBackendStage = "solve_labeling";
using FlowGraph = maxflow::Graph<double, double, double>;

// libmaxflow's error callback (allocation failure); never returns.
void ThrowMaxflowError(const char* message) {
  ThrowError(
      ErrorCode::kResourceExhausted, kMaxflowBackendStage, std::string("maxflow: ") + message);
}

}  // namespace

LpSolution SolveWithMaxflow(const ReducedEnergy& reduced, const RunContext& ctx) {
  LINESURF_THROW_IF(reduced.HasHigherOrderTerms(),
                    kInvalidOptions,
                    kMaxflowBackendStage,
                    "backend maxflow is exact only without structural and parity terms; this "
                    "energy has "
                        << reduced.structural_weights.size() << " structural and "
                        << reduced.parity_weights.size()
                        << " parity groups with free cells (use clp, pdhg or auto)");
  const int n = static_cast<int>(reduced.NumFree());
  LpSolution solution;
  solution.columns.assign(reduced.NumFree(), 0.0);
  if (n > 0) {
    auto graph = std::make_unique<FlowGraph>(n, static_cast<int>(reduced.pairs.size()) + 1,
                                             &ThrowMaxflowError);
    graph->add_node(n);
    // x = 1 <=> node in the sink set, which cuts the source edge: cap_source = cost of full.
    for (int i = 0; i < n; ++i) {
      const double u = reduced.unary[static_cast<std::size_t>(i)];
      graph->add_tweights(i, u > 0.0 ? u : 0.0, u < 0.0 ? -u : 0.0);
    }
    for (const auto& p : reduced.pairs) {
      graph->add_edge(static_cast<int>(p.a), static_cast<int>(p.b), p.weight, p.weight);
    }
    LINESURF_THROW_IF(
        ctx.ShouldStop(), kCancelled, kMaxflowBackendStage, "cancelled before max-flow");
    graph->maxflow();
    for (int i = 0; i < n; ++i) {
      if (graph->what_segment(i, FlowGraph::SOURCE) == FlowGraph::SINK) {
        solution.columns[static_cast<std::size_t>(i)] = 1.0;
      }
    }
  }
  solution.objective = reduced.Evaluate(solution.columns);
  solution.status = "optimal";
  return solution;
}

}  // namespace linesurf::solver
