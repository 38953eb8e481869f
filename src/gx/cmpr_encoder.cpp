// The CMPR encoder for the console's 3/8-5/8 palette (cmpr_encoder.h).
#include "gx/cmpr_encoder.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <tuple>
#include <utility>
#include <vector>

#include "core/error.h"
#include "gx/texture_decoder.h"

namespace lt::gx {

namespace {

constexpr int kFieldBits[3] = {5, 6, 5};  // r, g, b of an RGB565 endpoint
using Fields = std::array<int, 3>;

u16 pack_rgb565(const Fields& f) {
  return static_cast<u16>(f[0] << 11 | f[1] << 5 | f[2]);
}

// The block's texels that count: opaque ones carry colour, transparent ones need colour 3.
struct CmprBlockTexels {
  int opaque = 0;
  std::array<int, 16> slot{};  // texel number of the k-th opaque texel
  std::array<Fields, 16> rgb{};
  unsigned transparent = 0;  // texel bits
};

enum class Mode { Four, Three };

// The (c1, c2) order that makes the decoder use `mode`: four colours need c1 > c2; equal
// endpoints fall to three colours, which then holds the same colour three times.
std::pair<u16, u16> ordered_for_mode(const Fields& p, const Fields& q, Mode mode) {
  const u16 a = pack_rgb565(p), b = pack_rgb565(q);
  if (mode == Mode::Four) return a >= b ? std::pair{a, b} : std::pair{b, a};
  return a <= b ? std::pair{a, b} : std::pair{b, a};
}

struct Scored {
  long long error = std::numeric_limits<long long>::max();
  Fields p{}, q{};
  Mode mode = Mode::Four;
};

// The block's squared RGB error decoded as the console decodes it; `indices` (optional) gets
// each opaque texel's colour number.
long long score_endpoints(const CmprBlockTexels& block, u16 c1, u16 c2,
                          std::array<u8, 16>* indices) {
  const std::array<Color8, 4> palette = cmpr_palette(c1, c2);
  const int choices = c1 > c2 ? 4 : 3;  // colour 3 of the three-colour mode is transparent
  long long total = 0;
  for (int k = 0; k < block.opaque; ++k) {
    int best = 0;
    long long best_error = std::numeric_limits<long long>::max();
    for (int i = 0; i < choices; ++i) {
      long long e = 0;
      for (int c = 0; c < 3; ++c) {
        const int d = palette[static_cast<size_t>(i)][c] -
                      block.rgb[static_cast<size_t>(k)][static_cast<size_t>(c)];
        e += d * d;
      }
      if (e < best_error) {
        best_error = e;
        best = i;
      }
    }
    total += best_error;
    if (indices) (*indices)[static_cast<size_t>(k)] = static_cast<u8>(best);
  }
  return total;
}

void consider_endpoints(const CmprBlockTexels& block, const Fields& p, const Fields& q,
                        bool three_only, Scored& best) {
  for (Mode mode : {Mode::Four, Mode::Three}) {
    if (three_only && mode == Mode::Four) continue;
    const auto [c1, c2] = ordered_for_mode(p, q, mode);
    if (three_only && c1 > c2) continue;
    const long long e = score_endpoints(block, c1, c2, nullptr);
    if (e < best.error) best = {e, p, q, mode};
  }
}

int clamp_field(long v, int channel) {
  return static_cast<int>(std::clamp<long>(v, 0, (1L << kFieldBits[channel]) - 1));
}

// The nearest endpoint to a colour given in 8-bit units (rounded, clamped).
Fields nearest_fields(const double colour[3]) {
  Fields f{};
  for (int c = 0; c < 3; ++c) {
    const int v = static_cast<int>(std::lround(std::clamp(colour[c], 0.0, 255.0)));
    f[static_cast<size_t>(c)] = quantise_component(v, kFieldBits[c], Rounding::Nearest);
  }
  return f;
}

// For one 8-bit value and a field width: the endpoint pair (a, b) whose 5/8 a + 3/8 b
// (truncated, as decoded) is nearest to it, and the pair whose floored average is.
struct SinglePair {
  u8 a = 0, b = 0;
};
struct SingleTables {
  std::array<std::array<SinglePair, 256>, 2> blend, average;  // [0] 5 bits, [1] 6 bits
};

const SingleTables& single_tables() {
  static const SingleTables tables = [] {
    SingleTables t;
    for (int w = 0; w < 2; ++w) {
      const int top = w == 0 ? 31 : 63;
      const auto ex = [&](int v) { return w == 0 ? bits5_to_8(v) : bits6_to_8(v); };
      for (int v = 0; v < 256; ++v) {
        int best_blend = 1 << 20, best_average = 1 << 20;
        for (int a = 0; a <= top; ++a)
          for (int b = 0; b <= top; ++b) {
            const int blend = std::abs(((ex(a) * 5 + ex(b) * 3) >> 3) - v);
            const int average = std::abs((ex(a) + ex(b)) / 2 - v);
            if (blend < best_blend) {
              best_blend = blend;
              t.blend[static_cast<size_t>(w)][static_cast<size_t>(v)] = {static_cast<u8>(a),
                                                                         static_cast<u8>(b)};
            }
            if (average < best_average) {
              best_average = average;
              t.average[static_cast<size_t>(w)][static_cast<size_t>(v)] = {static_cast<u8>(a),
                                                                           static_cast<u8>(b)};
            }
          }
      }
    }
    return t;
  }();
  return tables;
}

// Endpoints solving least squares for fixed colour numbers: texel k is w_k c1 + (1 - w_k) c2
// with the console's weights (1, 0, 5/8, 3/8; the three-colour mode 1, 0, 1/2).
bool least_squares(const CmprBlockTexels& block, const std::array<u8, 16>& idx, Mode mode,
                   Fields& p, Fields& q) {
  const double four[4] = {1.0, 0.0, 5.0 / 8.0, 3.0 / 8.0}, three[3] = {1.0, 0.0, 0.5};
  double aa = 0, ab = 0, bb = 0, ax[3] = {}, bx[3] = {};
  for (int k = 0; k < block.opaque; ++k) {
    const double w = mode == Mode::Four ? four[idx[static_cast<size_t>(k)]]
                                        : three[std::min<int>(idx[static_cast<size_t>(k)], 2)];
    aa += w * w;
    ab += w * (1 - w);
    bb += (1 - w) * (1 - w);
    for (int c = 0; c < 3; ++c) {
      ax[c] += w * block.rgb[static_cast<size_t>(k)][static_cast<size_t>(c)];
      bx[c] += (1 - w) * block.rgb[static_cast<size_t>(k)][static_cast<size_t>(c)];
    }
  }
  const double det = aa * bb - ab * ab;
  if (std::abs(det) < 1e-9) return false;
  double a[3], b[3];
  for (int c = 0; c < 3; ++c) {
    a[c] = (bb * ax[c] - ab * bx[c]) / det;
    b[c] = (aa * bx[c] - ab * ax[c]) / det;
  }
  p = nearest_fields(a);
  q = nearest_fields(b);
  return true;
}

// Cluster fit for the console's weights (squish's ClusterFit idea, Brown 2006, with the
// console's 1, 5/8, 3/8, 0 in place of DXT1's thirds): the texels ordered along the principal
// axis, every split of that order into runs taking colours 0, 2, 3, 1 (four colours) or 0, 2, 1
// (three), least-squares endpoints for each split; the `keep` splits of least unquantised error
// become candidates.
struct Split {
  double error;
  double a[3], b[3];
};

void cluster_fit(const CmprBlockTexels& block, const double axis[3], const double mean[3],
                 Mode mode, std::vector<Split>& out) {
  const int n = block.opaque;
  std::array<int, 16> order{};
  std::array<double, 16> along{};
  for (int k = 0; k < n; ++k) {
    order[static_cast<size_t>(k)] = k;
    double t = 0;
    for (int c = 0; c < 3; ++c)
      t += (block.rgb[static_cast<size_t>(k)][static_cast<size_t>(c)] - mean[c]) * axis[c];
    along[static_cast<size_t>(k)] = t;
  }
  std::sort(order.begin(), order.begin() + n, [&](int p, int q) {
    return along[static_cast<size_t>(p)] > along[static_cast<size_t>(q)];
  });
  // prefix[i][c]: the sum of the first i ordered texels' channel c.
  std::array<std::array<double, 3>, 17> prefix{};
  for (int i = 0; i < n; ++i)
    for (int c = 0; c < 3; ++c)
      prefix[static_cast<size_t>(i + 1)][static_cast<size_t>(c)] =
          prefix[static_cast<size_t>(i)][static_cast<size_t>(c)] +
          block.rgb[static_cast<size_t>(order[static_cast<size_t>(i)])][static_cast<size_t>(c)];
  const auto run = [&](int from, int to, int c) {
    return prefix[static_cast<size_t>(to)][static_cast<size_t>(c)] -
           prefix[static_cast<size_t>(from)][static_cast<size_t>(c)];
  };
  // Runs [0, i) weight 1, [i, j) w2, [j, k) w3, [k, n) weight 0 (three colours: j == k).
  const double w2 = mode == Mode::Four ? 5.0 / 8.0 : 0.5, w3 = 3.0 / 8.0;
  for (int i = 0; i <= n; ++i)
    for (int j = i; j <= n; ++j)
      for (int k = j; k <= n; ++k) {
        if (mode == Mode::Three && k != j) break;
        const double n0 = i, n2 = j - i, n3 = k - j, n1 = n - k;
        const double aa = n0 + n2 * w2 * w2 + n3 * w3 * w3;
        const double bb = n1 + n2 * (1 - w2) * (1 - w2) + n3 * (1 - w3) * (1 - w3);
        const double ab = n2 * w2 * (1 - w2) + n3 * w3 * (1 - w3);
        const double det = aa * bb - ab * ab;
        if (std::abs(det) < 1e-9) continue;
        Split split{0, {}, {}};
        for (int c = 0; c < 3; ++c) {
          const double ax = run(0, i, c) + w2 * run(i, j, c) + w3 * run(j, k, c);
          const double bx = (1 - w2) * run(i, j, c) + (1 - w3) * run(j, k, c) + run(k, n, c);
          split.a[c] = std::clamp((bb * ax - ab * bx) / det, 0.0, 255.0);
          split.b[c] = std::clamp((aa * bx - ab * ax) / det, 0.0, 255.0);
          // The squared error less the constant sum of x^2.
          split.error += split.a[c] * split.a[c] * aa + split.b[c] * split.b[c] * bb +
                         2 * split.a[c] * split.b[c] * ab - 2 * split.a[c] * ax -
                         2 * split.b[c] * bx;
        }
        out.push_back(split);
      }
}

Scored search_endpoints(const CmprBlockTexels& block) {
  const bool three_only = block.transparent != 0;
  Scored best;
  // The colours' mean, principal axis (power iteration on the covariance) and bounding box.
  double mean[3] = {}, cov[3][3] = {}, lo[3] = {255, 255, 255}, hi[3] = {0, 0, 0};
  for (int k = 0; k < block.opaque; ++k)
    for (int c = 0; c < 3; ++c) {
      const double v = block.rgb[static_cast<size_t>(k)][static_cast<size_t>(c)];
      mean[c] += v / block.opaque;
      lo[c] = std::min(lo[c], v);
      hi[c] = std::max(hi[c], v);
    }
  for (int k = 0; k < block.opaque; ++k)
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        cov[i][j] += (block.rgb[static_cast<size_t>(k)][static_cast<size_t>(i)] - mean[i]) *
                     (block.rgb[static_cast<size_t>(k)][static_cast<size_t>(j)] - mean[j]);
  double axis[3] = {1, 1, 1};
  for (int iteration = 0; iteration < 8; ++iteration) {
    double next[3] = {};
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) next[i] += cov[i][j] * axis[j];
    const double norm = std::sqrt(next[0] * next[0] + next[1] * next[1] + next[2] * next[2]);
    if (norm < 1e-12) break;
    for (int i = 0; i < 3; ++i) axis[i] = next[i] / norm;
  }
  double tmin = 0, tmax = 0;
  for (int k = 0; k < block.opaque; ++k) {
    double t = 0;
    for (int c = 0; c < 3; ++c)
      t += (block.rgb[static_cast<size_t>(k)][static_cast<size_t>(c)] - mean[c]) * axis[c];
    tmin = std::min(tmin, t);
    tmax = std::max(tmax, t);
  }
  double e0[3], e1[3];
  for (int c = 0; c < 3; ++c) {
    e0[c] = mean[c] + axis[c] * tmax;
    e1[c] = mean[c] + axis[c] * tmin;
  }
  consider_endpoints(block, nearest_fields(e0), nearest_fields(e1), three_only, best);
  consider_endpoints(block, nearest_fields(hi), nearest_fields(lo), three_only, best);
  // The best pair for the mean colour alone (exact for a one-colour block).
  const SingleTables& tables = single_tables();
  Fields bp{}, bq{}, ap{}, aq{};
  for (int c = 0; c < 3; ++c) {
    const size_t w = kFieldBits[c] == 5 ? 0 : 1;
    const size_t v = static_cast<size_t>(std::lround(mean[c]));
    bp[static_cast<size_t>(c)] = tables.blend[w][v].a;
    bq[static_cast<size_t>(c)] = tables.blend[w][v].b;
    ap[static_cast<size_t>(c)] = tables.average[w][v].a;
    aq[static_cast<size_t>(c)] = tables.average[w][v].b;
  }
  consider_endpoints(block, bp, bq, three_only, best);
  consider_endpoints(block, ap, aq, three_only, best);
  consider_endpoints(block, nearest_fields(mean), nearest_fields(mean), three_only, best);
  std::vector<Split> splits;
  for (Mode mode : {Mode::Four, Mode::Three}) {
    if (three_only && mode == Mode::Four) continue;
    splits.clear();
    cluster_fit(block, axis, mean, mode, splits);
    const size_t keep = std::min<size_t>(4, splits.size());
    std::partial_sort(splits.begin(), splits.begin() + static_cast<std::ptrdiff_t>(keep),
                      splits.end(),
                      [](const Split& x, const Split& y) { return x.error < y.error; });
    for (size_t k = 0; k < keep; ++k)
      consider_endpoints(block, nearest_fields(splits[k].a), nearest_fields(splits[k].b),
                         three_only, best);
  }
  // Least squares for the best candidate's colour numbers, twice.
  for (int round = 0; round < 2; ++round) {
    std::array<u8, 16> idx{};
    const auto [c1, c2] = ordered_for_mode(best.p, best.q, best.mode);
    score_endpoints(block, c1, c2, &idx);
    Fields p, q;
    if (least_squares(block, idx, best.mode, p, q))
      consider_endpoints(block, p, q, three_only, best);
  }
  // Hill climbing: one endpoint field by one step, while the error falls.
  for (int step = 0; step < 64 && best.error > 0; ++step) {
    const Scored start = best;
    // Moves of one endpoint's field (dp or dq zero) or of both endpoints' same field; none off
    // a field's range.
    for (int c = 0; c < 3; ++c)
      for (const auto& [dp, dq] :
           {std::pair{-1, 0}, {1, 0}, {0, -1}, {0, 1}, {-1, -1}, {1, 1}, {-1, 1}, {1, -1}}) {
        Fields p = start.p, q = start.q;
        int& fp = p[static_cast<size_t>(c)];
        int& fq = q[static_cast<size_t>(c)];
        if (clamp_field(fp + dp, c) != fp + dp || clamp_field(fq + dq, c) != fq + dq) continue;
        fp += dp;
        fq += dq;
        const auto [c1, c2] = ordered_for_mode(p, q, start.mode);
        if (start.mode == Mode::Four && c1 == c2) continue;
        const long long err = score_endpoints(block, c1, c2, nullptr);
        if (err < best.error) best = {err, p, q, start.mode};
      }
    if (best.error >= start.error) break;
  }
  return best;
}

}  // namespace

std::array<u8, 8> encode_cmpr_block(const std::array<Color8, 16>& texels, unsigned valid) {
  CmprBlockTexels block;
  for (int k = 0; k < 16; ++k) {
    if ((valid >> k & 1u) == 0) continue;
    const Color8& c = texels[static_cast<size_t>(k)];
    if (c.a < 128) {
      block.transparent |= 1u << k;
      continue;
    }
    block.slot[static_cast<size_t>(block.opaque)] = k;
    block.rgb[static_cast<size_t>(block.opaque)] = {c.r, c.g, c.b};
    ++block.opaque;
  }
  std::array<u8, 8> out{};
  std::array<u8, 16> number{};  // per texel; padding texels keep 0
  u16 c1 = 0, c2 = 0;           // no opaque texel: equal endpoints, the three-colour mode
  if (block.opaque > 0) {
    const Scored best = search_endpoints(block);
    std::tie(c1, c2) = ordered_for_mode(best.p, best.q, best.mode);
    std::array<u8, 16> idx{};
    score_endpoints(block, c1, c2, &idx);
    for (int k = 0; k < block.opaque; ++k)
      number[static_cast<size_t>(block.slot[static_cast<size_t>(k)])] = idx[static_cast<size_t>(k)];
  }
  for (int k = 0; k < 16; ++k)
    if ((block.transparent >> k & 1u) != 0) number[static_cast<size_t>(k)] = 3;
  LT_CHECK(block.transparent == 0 || c1 <= c2, "a block with transparent texels uses 3 colours");
  out[0] = static_cast<u8>(c1 >> 8);
  out[1] = static_cast<u8>(c1);
  out[2] = static_cast<u8>(c2 >> 8);
  out[3] = static_cast<u8>(c2);
  for (int row = 0; row < 4; ++row) {
    int bits = 0;
    for (int x = 0; x < 4; ++x) bits |= number[static_cast<size_t>(row * 4 + x)] << (6 - 2 * x);
    out[static_cast<size_t>(4 + row)] = static_cast<u8>(bits);
  }
  return out;
}

EncodedLevel encode_cmpr(const Rgba8Image& image) {
  EncodedLevel out;
  out.format = TexFormat::CMPR;
  out.width = image.width;
  out.height = image.height;
  out.data.assign(level_bytes(TexFormat::CMPR, image.width, image.height), 0);
  for (int by = 0; by < image.height; by += 4) {
    for (int bx = 0; bx < image.width; bx += 4) {
      std::array<Color8, 16> texels{};
      unsigned valid = 0;
      for (int k = 0; k < 16; ++k) {
        const int x = bx + (k & 3), y = by + (k >> 2);
        if (x >= image.width || y >= image.height) continue;
        texels[static_cast<size_t>(k)] = image.at(x, y);
        valid |= 1u << k;
      }
      const std::array<u8, 8> bytes = encode_cmpr_block(texels, valid);
      const size_t at = texel_address(TexFormat::CMPR, image.width, bx, by).byte;
      std::copy(bytes.begin(), bytes.end(), out.data.begin() + static_cast<std::ptrdiff_t>(at));
    }
  }
  return out;
}

}  // namespace lt::gx
