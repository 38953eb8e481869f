// Triangle strips (src/mesh/triangle_strips.h): every triangle of the list is drawn exactly once
// with its winding, and every other triangle of the strip is a degenerate join. The strip is
// read back here by replaying Dolphin's software setup unit (SetupUnit.cpp SetupTriStrip: three
// vertex slots, the pointer to the oldest moved into slot 2 - (count & 1) after each triangle),
// not by the library's parity rule, so the two readings check each other.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <random>

#include "mesh/triangle_strips.h"

namespace lt {
namespace {

using Triangle = std::array<std::uint32_t, 3>;

// The triangles Dolphin's setup unit forms from a strip's vertices, slot by slot.
std::vector<Triangle> setup_unit_strip(const std::vector<std::uint32_t>& strip) {
  std::array<std::uint32_t, 3> slots{};  // m_Vertices
  std::array<int, 3> pointer{0, 1, 2};   // m_VertPointer, as slot numbers
  int write = 0, counter = 0;
  std::vector<Triangle> out;
  for (std::uint32_t v : strip) {
    slots[static_cast<size_t>(write)] = v;
    if (counter < 2) {
      ++counter;
      write = pointer[static_cast<size_t>(counter)];
      continue;
    }
    out.push_back({slots[static_cast<size_t>(pointer[0])], slots[static_cast<size_t>(pointer[1])],
                   slots[static_cast<size_t>(pointer[2])]});
    ++counter;
    pointer[static_cast<size_t>(2 - (counter & 1))] = pointer[0];
    write = pointer[0];
    pointer[0] = (counter + 1) % 3;
  }
  return out;
}

bool degenerate(const Triangle& t) { return t[0] == t[1] || t[1] == t[2] || t[0] == t[2]; }

// The triangle rotated so its smallest index comes first: the same winding compares equal.
Triangle canonical(Triangle t) {
  while (t[0] != std::min({t[0], t[1], t[2]})) t = {t[1], t[2], t[0]};
  return t;
}

// A w x h grid of quads, two triangles each, counter-clockwise; `pieces` copies side by side
// with no shared vertex, so the strip must jump between them.
std::vector<std::uint32_t> grid(int w, int h, int pieces, std::uint32_t* vertex_count) {
  std::vector<std::uint32_t> tris;
  const std::uint32_t per_piece = static_cast<std::uint32_t>((w + 1) * (h + 1));
  for (int p = 0; p < pieces; ++p) {
    const std::uint32_t base = per_piece * static_cast<std::uint32_t>(p);
    auto at = [&](int x, int y) { return base + static_cast<std::uint32_t>(y * (w + 1) + x); };
    for (int y = 0; y < h; ++y) {
      for (int x = 0; x < w; ++x) {
        tris.insert(tris.end(), {at(x, y), at(x + 1, y), at(x + 1, y + 1)});
        tris.insert(tris.end(), {at(x, y), at(x + 1, y + 1), at(x, y + 1)});
      }
    }
  }
  *vertex_count = per_piece * static_cast<std::uint32_t>(pieces);
  return tris;
}

void expect_each_triangle_once(const std::vector<std::uint32_t>& list, std::uint32_t vertices) {
  const std::vector<std::uint32_t> strip = triangle_strip(list, vertices);
  std::map<Triangle, int> wanted;
  for (size_t i = 0; i < list.size(); i += 3) ++wanted[canonical({list[i], list[i + 1], list[i + 2]})];
  std::map<Triangle, int> drawn;
  size_t degenerates = 0;
  const std::vector<Triangle> drawn_list = setup_unit_strip(strip);
  for (const Triangle& t : drawn_list) {
    if (degenerate(t)) ++degenerates;
    else ++drawn[canonical(t)];
  }
  EXPECT_EQ(drawn, wanted);  // each list triangle once, with its winding; nothing else with area
  EXPECT_EQ(drawn_list.size(), list.size() / 3 + degenerates);
  // The library's own reading of the strip is the setup unit's.
  EXPECT_EQ(strip_triangles(strip), drawn_list);
}

TEST(MeshTriangleStrips, AGridIsDrawnWithEveryTriangleOnceAndFewerIndicesThanAList) {
  std::uint32_t n = 0;
  const auto list = grid(16, 12, 1, &n);
  expect_each_triangle_once(list, n);
  const auto strip = triangle_strip(list, n);
  // 384 triangles: a list sends 1152 indices; strips of a grid about one index a triangle plus
  // the joins.
  EXPECT_LT(strip.size(), list.size() / 2);
}

TEST(MeshTriangleStrips, SeparatePiecesAreJoinedByDegenerateTriangles) {
  std::uint32_t n = 0;
  const auto list = grid(3, 2, 5, &n);
  expect_each_triangle_once(list, n);
  const auto drawn = setup_unit_strip(triangle_strip(list, n));
  // Five pieces with no vertex in common: at least four joins, each of degenerate triangles.
  EXPECT_GE(std::count_if(drawn.begin(), drawn.end(), degenerate), 4);
}

TEST(MeshTriangleStrips, ASeededTriangleSoupKeepsEveryTriangleAndItsWinding) {
  std::mt19937 rng(46);
  std::uniform_int_distribution<std::uint32_t> vertex(0, 59);
  std::vector<std::uint32_t> list;
  while (list.size() < 3 * 200) {
    const Triangle t{vertex(rng), vertex(rng), vertex(rng)};
    if (!degenerate(t)) list.insert(list.end(), t.begin(), t.end());
  }
  expect_each_triangle_once(list, 60);
}

TEST(MeshTriangleStrips, TheStripRuleAlternatesTheLastTwoVertices) {
  const std::vector<std::uint32_t> strip{7, 8, 9, 10, 11};
  EXPECT_EQ(strip_triangles(strip),
            (std::vector<Triangle>{{7, 8, 9}, {8, 10, 9}, {9, 10, 11}}));
  EXPECT_TRUE(triangle_strip(std::vector<std::uint32_t>{}, 0).empty());
}

}  // namespace
}  // namespace lt
