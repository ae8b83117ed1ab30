#include "engine/core/strong_id.h"

#include <gtest/gtest.h>

#include "engine/core/csr.h"

namespace linesurf {
namespace {

TEST(StrongId, DefaultIsInvalid) {
  EXPECT_FALSE(CellId().IsValid());
  EXPECT_TRUE(CellId(0u).IsValid());
  EXPECT_LT(CellId(1u), CellId(2u));
}

TEST(Csr, RowsKeepTheirItems) {
  Csr<FacetId, int> rows;
  rows.AddRow(std::vector<int>{1, 2, 3});
  rows.AddRow(std::vector<int>{});
  rows.AddRow(std::vector<int>{4});
  ASSERT_EQ(rows.NumRows(), 3u);
  EXPECT_EQ(rows[FacetId(0u)].size(), 3u);
  EXPECT_EQ(rows[FacetId(1u)].size(), 0u);
  EXPECT_EQ(rows[FacetId(2u)][0], 4);
}

}  // namespace
}  // namespace linesurf
