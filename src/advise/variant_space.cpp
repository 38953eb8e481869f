#include "advise/variant_space.h"

#include <optional>
#include <vector>

#include "core/error.h"
#include "paths/arbfp/arb_variant.h"
#include "paths/combiners/cube_lobe.h"
#include "paths/combiners/lobe_table.h"
#include "paths/gx/gx_variant.h"

namespace lt::advise {

namespace {

double bytes_per_texel(model::LutFormat f) {
  switch (f) {
    case model::LutFormat::U8:
      return 1;  // GL_LUMINANCE8
    case model::LutFormat::F16:
      return 2;  // GL_LUMINANCE16F_ARB
    case model::LutFormat::F32:
      return 4;  // GL_LUMINANCE32F_ARB
  }
  return 4;
}

// pow=... for every method, every LUT width and format; each also with :guards=all, the same
// image from a longer program (arb_guards.h keeps by default only the guards the scene can
// trigger), so never the cheaper of the two.
VariantSpace arbfp_space() {
  using arbfp::PowMethod;
  VariantSpace s;
  std::vector<arbfp::PowVariant> keys;
  arbfp::PowVariant v;
  for (PowMethod m : {PowMethod::Mul, PowMethod::Exact, PowMethod::Sg, PowMethod::SgSimplified,
                      PowMethod::SgFitted}) {
    v.method = m;
    keys.push_back(v);
  }
  v.method = PowMethod::Mul;
  v.per_vertex = true;
  keys.push_back(v);
  v = {};
  v.method = PowMethod::Lut;
  for (model::LutFormat f : {model::LutFormat::U8, model::LutFormat::F16, model::LutFormat::F32}) {
    for (int n : kLutWidths) {
      v.lut_size = n;
      v.lut_format = f;
      keys.push_back(v);
    }
  }
  for (const arbfp::PowVariant& key : keys) {
    Candidate c;
    c.variant = key.name();
    if (key.method == PowMethod::Lut)
      c.texture_bytes = key.lut_size * bytes_per_texel(key.lut_format);
    s.candidates.push_back(c);
  }
  const size_t plain = s.candidates.size();
  for (size_t i = 0; i < plain; ++i) {
    arbfp::PowVariant guarded = arbfp::parse_variant(s.candidates[i].variant);
    guarded.all_guards = true;
    Candidate c = s.candidates[i];
    c.variant = guarded.name();
    c.never_cheaper =
        "every hard-case guard, also those the scene cannot trigger: the same image "
        "as " +
        s.candidates[i].variant + " from more instructions (arb_guards.h)";
    c.same_image_as = s.candidates[i].variant;
    s.candidates.push_back(c);
  }
  return s;
}

// t=vertex and t=texgen, each with every LUT width, and lobe=xf-spec (no texture); with a
// colour thickness map, each also with :map=rgb565 (half the map's bytes) and :map=cmpr (an
// eighth), with a grey one :map=i4 (half). The formats that cost as much as one of these and
// keep fewer bits (rgb5a3, ia8, ia4) are left out.
VariantSpace gx_space(const Scene& scene) {
  VariantSpace s;
  double colour_map_texels = 0, grey_map_texels = 0;
  for (const Material& m : scene.materials) {
    if (m.translucency && m.translucency->thickness_map) {
      const auto& t = m.translucency->thickness_map->texture;
      double& texels = m.translucency->thickness_map->grey ? grey_map_texels : colour_map_texels;
      texels = std::max(texels, static_cast<double>(t.width) * t.height);
    }
  }
  std::vector<gx::GxVariant> keys;
  for (gx::GxVariant::TexCoord t :
       {gx::GxVariant::TexCoord::Vertex, gx::GxVariant::TexCoord::Texgen}) {
    for (int n : kLutWidths) {
      gx::GxVariant v;
      v.t = t;
      v.lut_size = n;
      keys.push_back(v);
    }
  }
  // base=tev changes only the passes of directional lights (pass_planner.cpp): without one it
  // is the same program.
  const bool directional =
      std::any_of(scene.lights.begin(), scene.lights.end(),
                  [](const Light& l) { return l.type == Light::Type::Directional; });
  if (directional) {
    const size_t lut_keys = keys.size();
    for (size_t i = 0; i < lut_keys; ++i) {
      gx::GxVariant v = keys[i];
      v.base_in_tev = true;
      keys.push_back(v);
    }
  }
  gx::GxVariant xf;
  xf.lobe = gx::GxVariant::Lobe::XfSpec;
  keys.push_back(xf);
  // The default (t=vertex, 256 texels) first.
  std::stable_partition(keys.begin(), keys.end(),
                        [](const gx::GxVariant& v) { return v == gx::GxVariant{}; });
  std::vector<std::optional<gx::TexFormat>> map_formats{std::nullopt};
  if (colour_map_texels > 0) {
    map_formats.push_back(gx::TexFormat::RGB565);
    map_formats.push_back(gx::TexFormat::CMPR);
  }
  if (grey_map_texels > 0) map_formats.push_back(gx::TexFormat::I4);
  // The bytes a texel of the map takes in that format (texture_format.h).
  auto map_bytes = [](const gx::GxVariant& v, bool grey, double texels) {
    return texels * gx::format_info(gx::map_texture_format(v, grey)).bits_per_texel / 8.0;
  };
  for (const std::optional<gx::TexFormat>& format : map_formats) {
    for (gx::GxVariant v : keys) {
      v.map_format = format;
      Candidate c;
      c.variant = gx::to_string(v);
      // GX_TF_I8 LUT [OGC gx.h GX_TF_I8]; the maps in their formats.
      c.texture_bytes = (v.lobe == gx::GxVariant::Lobe::Lut ? v.lut_size : 0) +
                        map_bytes(v, false, colour_map_texels) +
                        map_bytes(v, true, grey_map_texels);
      s.candidates.push_back(c);
    }
  }
  if (colour_map_texels == 0)
    s.left_out.push_back(
        ":map=rgb565, :map=cmpr: no material has a colour thickness map (the same image)");
  if (grey_map_texels == 0)
    s.left_out.push_back(":map=i4: no material has a grey thickness map (the same image)");
  s.left_out.push_back(
      ":colors=round, :lights=round-each: which of Dolphin's two emulations models the console "
      "(gx-hardware.md §2.4, §2.5), not a choice a port makes");
  s.left_out.push_back(
      ":coverage=console: the console's sample point instead of Dolphin's (gx-hardware.md "
      "§2.6), not a choice a port makes");
  if (!directional) s.left_out.push_back(":base=tev: no directional light (the same program)");
  s.left_out.push_back(
      ":out=xfb: which image the path returns (the EFB or the TV's), not a program");
  return s;
}

// The three plans; t=vertex and t=texgen sample the 256-texel luminance table, lobe=cube a
// 256^2 x 6 RGBA8 cube map per directional light instead.
VariantSpace combiners_space(const Scene& scene) {
  VariantSpace s;
  double directional = 0;
  for (const Light& l : scene.lights) directional += l.type == Light::Type::Directional ? 1 : 0;
  s.candidates.push_back({"t=vertex", kCombinerLutSize, {}, {}});
  s.candidates.push_back({"t=texgen", kCombinerLutSize, {}, {}});
  s.candidates.push_back(
      {"lobe=cube", directional * kCombinerCubeSize * kCombinerCubeSize * 6.0 * 4.0, {}, {}});
  s.left_out.push_back("the lobe table's width: fixed at " + std::to_string(kCombinerLutSize) +
                       " texels (lobe_table.h), not a variant axis of the combiners path");
  return s;
}

}  // namespace

VariantSpace variant_space(const PathInfo& path, const Scene& scene) {
  VariantSpace s;
  if (path.name == "arbfp")
    s = arbfp_space();
  else if (path.name == "gx")
    s = gx_space(scene);
  else if (path.name == "combiners")
    s = combiners_space(scene);
  else
    LT_CHECK(false, "advise has no variant space for path " + path.name);
  LT_CHECK(!s.candidates.empty() && s.candidates.front().variant == path.variants.front().name,
           "the default variant of " + path.name + " must come first");
  s.left_out.push_back(
      "thickness map or vertex thickness: the scene decides (its \"thickness\" "
      "key), no variant of the path switches it");
  return s;
}

}  // namespace lt::advise
