#include "solver/energy/energy_input.h"

#include "engine/core/exception.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace linesurf::solver {
namespace {

constexpr const char* kEnergyInputStage = "energy_input";

Error Invalid(const std::string& message) {
  return Error{ErrorCode::kInvalidInput, kEnergyInputStage, message};
}

// Checks one CSR group family; returns an empty string when valid.
std::string CheckGroups(const char* name,
                        const std::vector<std::uint32_t>& offsets,
                        const std::vector<CellId>& cells,
                        std::size_t num_groups,
                        std::size_t num_cells) {
  std::ostringstream out;
  if (offsets.size() != num_groups + 1 || offsets.front() != 0 || offsets.back() != cells.size()) {
    out << name << ": offsets do not match " << num_groups << " groups of " << cells.size()
        << " cells";
    return out.str();
  }
  std::vector<CellId> sorted;
  for (std::size_t g = 0; g < num_groups; ++g) {
    if (offsets[g] > offsets[g + 1]) {
      out << name << " group " << g << ": decreasing offsets";
      return out.str();
    }
    sorted.assign(cells.begin() + offsets[g], cells.begin() + offsets[g + 1]);
    for (CellId c : sorted) {
      if (c.index() >= num_cells) {
        out << name << " group " << g << ": cell " << c.value() << " out of range";
        return out.str();
      }
    }
    std::sort(sorted.begin(), sorted.end());
    if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end()) {
      out << name << " group " << g << ": repeated cell";
      return out.str();
    }
  }
  return {};
}

std::string CheckWeights(const char* name, const std::vector<double>& weights) {
  for (std::size_t g = 0; g < weights.size(); ++g) {
    if (!std::isfinite(weights[g]) || weights[g] < 0.0) {
      std::ostringstream out;
      out << name << " " << g << ": weight " << weights[g] << " is not finite and >= 0";
      return out.str();
    }
  }
  return {};
}

}  // namespace

CellId EnergyInput::AddCell(double cost_if_empty_value, double cost_if_full_value, CellFix fix) {
  const CellId id = cost_if_empty.NextId();
  cost_if_empty.push_back(cost_if_empty_value);
  cost_if_full.push_back(cost_if_full_value);
  fixed.push_back(fix);
  return id;
}

void EnergyInput::ResizeCells(std::size_t num_cells) {
  cost_if_empty.raw().resize(num_cells, 0.0);
  cost_if_full.raw().resize(num_cells, 0.0);
  fixed.raw().resize(num_cells, CellFix::kFree);
}

std::vector<CellId> EnergyInput::FreeCells() const {
  std::vector<CellId> free;
  for (std::size_t c = 0; c < NumCells(); ++c) {
    if (fixed[CellId(c)] == CellFix::kFree) free.push_back(CellId(c));
  }
  return free;
}

void EnergyInput::AddPair(CellId a, CellId b, double weight) { pairs.push_back({a, b, weight}); }

void EnergyInput::AddStructuralGroup(std::span<const CellId> cells, double weight) {
  structural_cells.insert(structural_cells.end(), cells.begin(), cells.end());
  structural_offsets.push_back(static_cast<std::uint32_t>(structural_cells.size()));
  structural_weights.push_back(weight);
}

void EnergyInput::AddParityGroup(std::span<const CellId> cells,
                                 std::span<const std::int8_t> signs,
                                 double weight,
                                 std::int8_t constant) {
  LINESURF_ASSERT(cells.size() == signs.size());
  parity_cells.insert(parity_cells.end(), cells.begin(), cells.end());
  parity_signs.insert(parity_signs.end(), signs.begin(), signs.end());
  parity_offsets.push_back(static_cast<std::uint32_t>(parity_cells.size()));
  parity_weights.push_back(weight);
  parity_constants.push_back(constant);
}

Status EnergyInput::Validate() const {
  const std::size_t n = NumCells();
  if (cost_if_full.size() != n || fixed.size() != n) {
    return Invalid("per-cell vectors differ in size");
  }
  for (std::size_t c = 0; c < n; ++c) {
    const CellId id(c);
    if (!std::isfinite(cost_if_empty[id]) || !std::isfinite(cost_if_full[id])) {
      return Invalid("cell " + std::to_string(c) + ": cost is not finite");
    }
    if (fixed[id] != CellFix::kFree && fixed[id] != CellFix::kEmpty &&
        fixed[id] != CellFix::kFull) {
      return Invalid("cell " + std::to_string(c) + ": bad CellFix value");
    }
  }
  for (std::size_t p = 0; p < pairs.size(); ++p) {
    const PairTerm& t = pairs[p];
    if (t.a.index() >= n || t.b.index() >= n || t.a == t.b) {
      return Invalid("pair " + std::to_string(p) + ": cells out of range or equal");
    }
    if (!std::isfinite(t.weight) || t.weight < 0.0) {
      return Invalid("pair " + std::to_string(p) + ": weight is not finite and >= 0");
    }
  }
  std::string message =
      CheckGroups("structural", structural_offsets, structural_cells, structural_weights.size(), n);
  if (message.empty()) message = CheckWeights("structural group", structural_weights);
  if (message.empty()) {
    message = CheckGroups("parity", parity_offsets, parity_cells, parity_weights.size(), n);
  }
  if (message.empty() && parity_signs.size() != parity_cells.size()) {
    message = "parity: one sign per cell needed";
  }
  if (message.empty() && parity_constants.size() != parity_weights.size()) {
    message = "parity: one constant per group needed";
  }
  if (message.empty()) message = CheckWeights("parity group", parity_weights);
  if (message.empty()) {
    for (std::size_t i = 0; i < parity_signs.size(); ++i) {
      if (parity_signs[i] != 1 && parity_signs[i] != -1) {
        message = "parity sign " + std::to_string(i) + " is not +-1";
        break;
      }
    }
  }
  if (!message.empty()) return Invalid(message);
  return {};
}

double EnergyInput::Evaluate(std::span<const double> x) const {
  LINESURF_ASSERT(x.size() == NumCells());
  double energy = 0.0;
  for (std::size_t c = 0; c < NumCells(); ++c) {
    energy += cost_if_empty[CellId(c)] * (1.0 - x[c]) + cost_if_full[CellId(c)] * x[c];
  }
  for (const PairTerm& t : pairs) energy += t.weight * std::abs(x[t.a.index()] - x[t.b.index()]);
  for (std::size_t g = 0; g < NumStructuralGroups(); ++g) {
    double sum = 0.0;
    for (CellId c : StructuralGroup(g)) sum += x[c.index()];
    energy += structural_weights[g] * std::max(0.0, 1.0 - sum);
  }
  for (std::size_t g = 0; g < NumParityGroups(); ++g) {
    const auto cells = ParityGroup(g);
    const auto signs = ParitySigns(g);
    double sum = parity_constants[g];
    for (std::size_t i = 0; i < cells.size(); ++i) sum += signs[i] * x[cells[i].index()];
    energy += parity_weights[g] * std::abs(sum);
  }
  return energy;
}

double EnergyInput::Evaluate(std::span<const std::uint8_t> labels) const {
  std::vector<double> x(labels.begin(), labels.end());
  return Evaluate(std::span<const double>(x));
}

}  // namespace linesurf::solver
