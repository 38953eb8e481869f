#include "paths/combiners/lobe_table.h"

#include <algorithm>

#include "gl/map_texture.h"
#include "image/image.h"
#include "model/power_lut.h"
#include "model/translucency.h"

namespace lt {

namespace {

// The texel as an 8-bit texture stores it: rounded to nearest of 255 steps, once.
float to_8_bits(double v) {
  return static_cast<float>(to_unorm8(v) / 255.0);
}

// The table's layout for `tr`, each texel `texel_of(lobe at the texel)` rounded once to 8 bits.
template <typename TexelOf>
LobeTable build(const Translucency& tr, TexelOf texel_of) {
  LobeTable out;
  std::vector<glm::dvec3> lobe;
  if (tr.ramp) {
    const model::Texture& ramp = tr.ramp->texture;
    out.width = ramp.width;
    out.channels = tr.ramp->grey ? 1 : 3;
    for (int i = 0; i < ramp.width; ++i) lobe.push_back(ramp.texel(i, 0));
  } else {
    model::PowerLut addressing;  // only its texel-centre remap
    addressing.size = kCombinerLutSize;
    out.width = addressing.size;
    out.scale = addressing.coordinate(1) - addressing.coordinate(0);
    out.offset = addressing.coordinate(0);
    for (int i = 0; i < out.width; ++i) {
      // The same t_i = i / (N - 1) as model::PowerLut::build.
      lobe.emplace_back(model::lobe(static_cast<double>(i) / (out.width - 1), tr.power));
    }
  }
  for (const glm::dvec3& v : lobe) {
    const glm::dvec3 texel = texel_of(v);
    for (int c = 0; c < out.channels; ++c) out.texels.push_back(to_8_bits(texel[c]));
  }
  return out;
}

}  // namespace

double lobe_gain(const Translucency& tr) {
  if (!tr.ramp) return 1;
  const std::vector<float>& t = tr.ramp->texture.texels;
  return std::max(1.0, static_cast<double>(*std::max_element(t.begin(), t.end())));
}

LobeTable lobe_table(const Translucency& tr) {
  const double gain = lobe_gain(tr);
  return build(tr, [gain](const glm::dvec3& lobe) { return lobe / gain; });
}

LobeTable map_lobe_table(const Translucency& tr, const Light& light) {
  const double s = light.translucency_scale, a = tr.ambient;
  const double full = lobe_gain(tr) * s + a;  // the largest lobe * s + a
  return build(
      tr, [&](const glm::dvec3& lobe) { return full > 0 ? (lobe * s + a) / full : glm::dvec3(0); });
}

GLuint upload_lobe_table(const LobeTable& table) {
  std::vector<unsigned char> bytes(table.texels.size());
  for (size_t i = 0; i < bytes.size(); ++i) {
    bytes[i] = to_unorm8(table.texels[i]);
  }
  const bool rgb = table.channels == 3;
  GLuint tex = 0;
  glGenTextures(1, &tex);
  glBindTexture(GL_TEXTURE_1D, tex);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage1D(GL_TEXTURE_1D, 0, rgb ? GL_RGB8 : GL_LUMINANCE8, table.width, 0,
               rgb ? GL_RGB : GL_LUMINANCE, GL_UNSIGNED_BYTE, bytes.data());
  // Linear between texel centres; CLAMP_TO_EDGE saturates t per pixel.
  gl::set_linear_clamp_to_edge(GL_TEXTURE_1D);
  glBindTexture(GL_TEXTURE_1D, 0);
  return tex;
}

}  // namespace lt
