#include "bake/uv_raster.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"

namespace lt::bake {

namespace {

// Sub-texel precision of the snapped vertices, as a GPU's 8 sub-pixel bits.
constexpr std::int64_t kSub = 256;

struct Point {
  std::int64_t x, y;  // image space (row 0 at the top), in 1/kSub texel
};

// Twice the signed area of (a, b, p): > 0 when p is on the left of a -> b in image space.
std::int64_t edge(const Point& a, const Point& b, const Point& p) {
  return (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x);
}

// With the corners ordered so that the inside is where every edge function is positive, a
// centre exactly on edge a -> b belongs to the triangle for one direction of the edge and not
// for the other: the two triangles sharing the edge see it in opposite directions, so exactly
// one of them takes it.
bool owns_edge(const Point& a, const Point& b) {
  const std::int64_t dx = b.x - a.x, dy = b.y - a.y;
  return dy > 0 || (dy == 0 && dx < 0);
}

}  // namespace

UvCoverage rasterize_uv(const std::vector<glm::dvec2>& uvs,
                        const std::vector<glm::uvec3>& triangles, int width, int height) {
  LT_CHECK(width > 0 && height > 0, "texture size");
  UvCoverage c;
  c.width = width;
  c.height = height;
  const std::size_t texels = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  c.triangle.assign(texels, -1);
  c.barycentric.assign(texels, glm::dvec3(0.0));
  std::vector<std::uint8_t> claims(texels, 0);
  // UVs far outside [0, 1] only cover texels that do not exist: clamped before snapping so the
  // integers stay small (a triangle spanning the clamp edge keeps its texels inside).
  auto snap = [&](const glm::dvec2& uv) {
    const double x = std::clamp(uv.x, -4.0, 5.0) * width;
    const double y = (1.0 - std::clamp(uv.y, -4.0, 5.0)) * height;
    return Point{std::llround(x * kSub), std::llround(y * kSub)};
  };
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    const glm::uvec3& tri = triangles[t];
    LT_CHECK(tri.x < uvs.size() && tri.y < uvs.size() && tri.z < uvs.size(), "uv index");
    Point p[3] = {snap(uvs[tri.x]), snap(uvs[tri.y]), snap(uvs[tri.z])};
    int corner[3] = {0, 1, 2};
    std::int64_t area = edge(p[0], p[1], p[2]);
    if (area == 0) {
      ++c.degenerate_in_uv;
      continue;
    }
    if (area < 0) {
      // Mirrored in UV: swap two corners so the inside is positive; the weights follow.
      std::swap(p[1], p[2]);
      std::swap(corner[1], corner[2]);
      area = -area;
    }
    // Texel centres (x + 0.5, y + 0.5) in the triangle's bounding box.
    auto first = [&](std::int64_t lo) {
      return std::max<std::int64_t>(0, (lo - kSub / 2 + kSub - 1) / kSub);
    };
    auto last = [&](std::int64_t hi, int size) {
      const std::int64_t v = hi - kSub / 2;
      return std::min<std::int64_t>(size - 1, v < 0 ? -1 : v / kSub);
    };
    const std::int64_t x0 = first(std::min({p[0].x, p[1].x, p[2].x}));
    const std::int64_t x1 = last(std::max({p[0].x, p[1].x, p[2].x}), width);
    const std::int64_t y0 = first(std::min({p[0].y, p[1].y, p[2].y}));
    const std::int64_t y1 = last(std::max({p[0].y, p[1].y, p[2].y}), height);
    const bool own[3] = {owns_edge(p[1], p[2]), owns_edge(p[2], p[0]), owns_edge(p[0], p[1])};
    // Which centres are covered is decided on the snapped corners (exactly); the weights come
    // from the unsnapped ones, so that the interpolated point is the texel centre itself.
    const glm::dvec2 q[3] = {uvs[tri[corner[0]]], uvs[tri[corner[1]]], uvs[tri[corner[2]]]};
    auto cross = [](const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& r) {
      return (b.x - a.x) * (r.y - a.y) - (b.y - a.y) * (r.x - a.x);
    };
    const double exact_area = cross(q[0], q[1], q[2]);
    for (std::int64_t y = y0; y <= y1; ++y) {
      for (std::int64_t x = x0; x <= x1; ++x) {
        const Point centre{x * kSub + kSub / 2, y * kSub + kSub / 2};
        // w[k]: the edge opposite corner k, proportional to corner k's barycentric weight.
        const std::int64_t w[3] = {edge(p[1], p[2], centre), edge(p[2], p[0], centre),
                                   edge(p[0], p[1], centre)};
        bool inside = true;
        for (int k = 0; k < 3 && inside; ++k) inside = w[k] > 0 || (w[k] == 0 && own[k]);
        if (!inside) continue;
        const std::size_t i = static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
                              static_cast<std::size_t>(x);
        if (claims[i] < 255) ++claims[i];
        if (claims[i] == 2) ++c.overlapping;
        if (c.triangle[i] >= 0) continue;  // the lowest triangle index keeps the texel
        c.triangle[i] = static_cast<std::int32_t>(t);
        glm::dvec3 b(0.0);
        const glm::dvec2 uv((static_cast<double>(x) + 0.5) / width,
                            1.0 - (static_cast<double>(y) + 0.5) / height);
        const double exact[3] = {cross(q[1], q[2], uv), cross(q[2], q[0], uv),
                                 cross(q[0], q[1], uv)};
        for (int k = 0; k < 3; ++k) {
          b[corner[k]] = exact_area != 0.0 ? exact[k] / exact_area
                                           : static_cast<double>(w[k]) / static_cast<double>(area);
        }
        c.barycentric[i] = b;
        ++c.covered;
      }
    }
  }
  return c;
}

std::size_t dilate(std::vector<double>& values, std::vector<char>& filled, int width, int height,
                   int passes) {
  const std::size_t texels = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  LT_CHECK(values.size() == texels && filled.size() == texels, "one value per texel");
  std::size_t added = 0;
  std::vector<std::size_t> ring;  // the texels a pass fills, written after it has looked
  std::vector<double> ring_values;
  for (int pass = 0; pass < passes; ++pass) {
    ring.clear();
    ring_values.clear();
    for (int y = 0; y < height; ++y) {
      for (int x = 0; x < width; ++x) {
        const std::size_t i = static_cast<std::size_t>(y) * width + static_cast<std::size_t>(x);
        if (filled[i]) continue;
        double sum = 0.0;
        int n = 0;
        for (int dy = -1; dy <= 1; ++dy) {
          for (int dx = -1; dx <= 1; ++dx) {
            const int nx = x + dx, ny = y + dy;
            if ((dx == 0 && dy == 0) || nx < 0 || ny < 0 || nx >= width || ny >= height) continue;
            const std::size_t j =
                static_cast<std::size_t>(ny) * width + static_cast<std::size_t>(nx);
            if (!filled[j]) continue;
            sum += values[j];
            ++n;
          }
        }
        if (n == 0) continue;
        ring.push_back(i);
        ring_values.push_back(sum / n);
      }
    }
    if (ring.empty()) break;
    for (std::size_t k = 0; k < ring.size(); ++k) {
      values[ring[k]] = ring_values[k];
      filled[ring[k]] = 1;
    }
    added += ring.size();
  }
  return added;
}

}  // namespace lt::bake
