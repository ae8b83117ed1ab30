#include "engine/core/csr.h"

#include "engine/core/strong_id.h"

#include <gtest/gtest.h>

#include <vector>

namespace linesurf {
namespace {

struct RowTag {};
struct ColTag {};
using RowId = StrongId<RowTag>;
using ColId = StrongId<ColTag>;

std::vector<std::uint32_t> Items(std::span<const std::uint32_t> row) {
  return {row.begin(), row.end()};
}

TEST(Csr, FromPairsGroupsByRowAndKeepsThePairOrder) {
  const std::vector<std::uint32_t> rows{2, 0, 2, 1, 0, 2};
  const auto csr = Csr<std::uint32_t, std::uint32_t>::FromPairs(
      4,
      rows.size(),
      [&](std::size_t i) { return rows[i]; },
      [](std::size_t i) { return static_cast<std::uint32_t>(10 * i); });
  ASSERT_EQ(csr.NumRows(), 4u);
  EXPECT_EQ(Items(csr[0]), (std::vector<std::uint32_t>{10, 40}));
  EXPECT_EQ(Items(csr[1]), (std::vector<std::uint32_t>{30}));
  EXPECT_EQ(Items(csr[2]), (std::vector<std::uint32_t>{0, 20, 50}));
  EXPECT_TRUE(csr[3].empty());
  EXPECT_EQ(csr.NumItems(), rows.size());
}

TEST(Csr, TransposeListsTheRowsOfEachItemInIncreasingOrder) {
  Csr<RowId, ColId> csr;
  csr.AddRow(std::vector<ColId>{ColId(std::size_t{2}), ColId(std::size_t{0})});
  csr.AddRow(std::vector<ColId>{});
  csr.AddRow(
      std::vector<ColId>{ColId(std::size_t{0}), ColId(std::size_t{2}), ColId(std::size_t{2})});
  const Csr<ColId, RowId> t = csr.Transpose(4);
  ASSERT_EQ(t.NumRows(), 4u);
  const auto rows = [&](std::size_t c) {
    std::vector<std::size_t> out;
    for (const RowId r : t[ColId(c)]) out.push_back(r.index());
    return out;
  };
  EXPECT_EQ(rows(0), (std::vector<std::size_t>{0, 2}));
  EXPECT_TRUE(rows(1).empty());
  EXPECT_EQ(rows(2), (std::vector<std::size_t>{0, 2, 2}));
  EXPECT_TRUE(rows(3).empty());
  // Transposing back gives the rows again, each sorted.
  const Csr<RowId, ColId> back = t.Transpose(3);
  ASSERT_EQ(back.NumRows(), 3u);
  EXPECT_EQ(back[RowId(std::size_t{0})].size(), 2u);
  EXPECT_EQ(back[RowId(std::size_t{0})][0], ColId(std::size_t{0}));
  EXPECT_TRUE(back[RowId(std::size_t{1})].empty());
  EXPECT_EQ(back[RowId(std::size_t{2})].size(), 3u);
}

}  // namespace
}  // namespace linesurf
