// The planner's albedo map (load/albedo_map.h): GX_TEXMAP2's texture, one more texgen at the
// mesh's UVs, and the map multiplied into each part of the pass's sum before the sum is formed.
//
// The map scales everything the pass adds (the diffuse channel, the translucency and pass 0's
// ambient), as the seed's cDiffuseAlbedo does. It cannot multiply the finished sum: a TEV
// input is 8 bits, so a sum the output scale would saturate (a bright backlight under a dark
// texel) would be clamped before the map darkens it. So the translucency is multiplied by the
// map in a stage of its own, which takes the translucency's scale over (the stage before now
// runs x1: w x COLOR0 <= 255), and the last stage reads the map too: out = (PREV + COLOR1 x TEXC)
// x sd, the lerp's b x c with d = PREV. A diffuse-only pass needs no stage more: COLOR0 x TEXC.
#include <algorithm>

#include "core/error.h"
#include "gx/texture_unit.h"
#include "model/texture_sampling.h"
#include "paths/gx/pass_plan_parts.h"

namespace lt::gx {

namespace {

int next_power_of_two(int n) {
  int p = 1;
  while (p < n) p *= 2;
  return p;
}

// `t` with each side that wraps (REPEAT, MIRRORED_REPEAT) at the next power of two, sampled
// bilinearly at the new texel centres with t's wrap modes; `t` itself when nothing changes.
model::Texture power_of_two_sides(const model::Texture& t) {
  model::Texture out = t;
  if (t.wrap_s != model::Wrap::ClampToEdge) out.width = next_power_of_two(t.width);
  if (t.wrap_t != model::Wrap::ClampToEdge) out.height = next_power_of_two(t.height);
  if (out.width == t.width && out.height == t.height) return out;
  out.texels.clear();
  for (int y = 0; y < out.height; ++y) {
    for (int x = 0; x < out.width; ++x) {
      const glm::dvec3 v =
          model::sample_bilinear(t, {(x + 0.5) / out.width, (y + 0.5) / out.height});
      for (int c = 0; c < 3; ++c) out.texels.push_back(static_cast<float>(v[c]));
    }
  }
  return out;
}

GxConst<NameGroup::TexWrap> gx_wrap(model::Wrap w) {
  switch (w) {
    case model::Wrap::Repeat:
      return {"GX_REPEAT"};
    case model::Wrap::MirroredRepeat:
      return {"GX_MIRROR"};
    case model::Wrap::ClampToEdge:
      break;
  }
  return {"GX_CLAMP"};
}

}  // namespace

std::optional<MapTexture> PassPlanner::albedo_texture(MaterialPlan& mp) const {
  const Material& mat = scene_.materials[static_cast<size_t>(mp.material)];
  if (!mat.albedo_map) return std::nullopt;
  const TextureMap& map = *mat.albedo_map;
  const model::Texture& t = map.texture;
  const std::string file = scene_.file.string(), key = "materials." + mat.name + ".albedo_map";
  // GX has no float texture format: an albedo over 1 (an EXR map) would need its scale moved
  // into both channels' material colours and the translucency light; the scene's "albedo" is
  // the place for a factor over 1.
  const float top = t.texels.empty() ? 0.0f : *std::max_element(t.texels.begin(), t.texels.end());
  if (top > 1.0f)
    throw InputError(file, key,
                     "gx: the albedo map holds values up to " + note_number(top) +
                         "; GX's 8-bit texture formats hold 0..1 (put the factor in \"albedo\")");
  // Planar textures repeat and mirror only at power-of-two sizes [OGC gx.h L4287-4288]: a side
  // that wraps and is not one is resampled to the next power of two, as a porter's texture
  // converter would (the reference's bilinear filter with the map's own wrap, at the new texel
  // centres); the loss shows in the error report, and the array's comment says so.
  const model::Texture pot = power_of_two_sides(t);
  const bool resized = pot.width != t.width || pot.height != t.height;
  MapTexture m =
      map_texture(mp, MapTexels{pot.width, pot.height, &pot.texels, map.grey}, kAlbedoMapRole);
  m.texture.wrap_s = gx_wrap(t.wrap_s);
  m.texture.wrap_t = gx_wrap(t.wrap_t);
  m.texture.what = std::string("The albedo map: ") + m.texture.format.name() + ", linear, " +
                   m.texture.wrap_s.name() + " x " + m.texture.wrap_t.name();
  if (resized) {
    const std::string from = std::to_string(t.width) + "x" + std::to_string(t.height);
    m.texture.what += " (resampled from " + from + ": GX wraps power-of-two sides only)";
    mp.arrays.back().what += "\nResampled bilinearly from the map's " + from +
                             " texels: GX_REPEAT and GX_MIRROR need power-of-two sides.";
  }
  return m;
}

void PassPlanner::add_albedo_stage(PassPlan& p, const MapTexture& albedo) {
  using ColourIn = GxConst<NameGroup::ColorArg>;
  p.vertex.uv = true;
  const int coord = static_cast<int>(p.texgens.size());
  p.texgens.push_back(map_texgen(albedo, coord, p.vertex.uv_attribute()));
  const GxConst<NameGroup::TexCoord> texcoord = GxConst<NameGroup::TexCoord>::with_value(coord);
  // The last stage reads the channel (RASC, a of the lerp) plus PREV (d) when the pass has a
  // translucency stage: b x c with c = the map instead.
  TevStagePlan last = p.stages.back();
  p.stages.pop_back();
  const bool adds_translucency = last.color.in[3] == ColourIn{"GX_CC_CPREV"};
  if (adds_translucency) {
    // PREV x TEXC at the translucency stage's scale, which becomes x1.
    TevStagePlan& trans = p.stages.back();
    const int scale = 1 << trans.color.scale.value();  // GX_CS_SCALE_1, _2, _4 are 0, 1, 2
    trans.color.scale = {"GX_CS_SCALE_1"};
    trans.frame_scale = TevStagePlan::FrameScale::None;
    trans.what = trans.what.substr(0, trans.what.rfind(" x ")) + " (x 1: the next stage scales)";
    const int k = static_cast<int>(p.stages.size());
    p.stages.push_back(tev_stage(k, texcoord, albedo.texture.map, {"GX_COLORNULL"},
                                 {"GX_CC_ZERO", "GX_CC_CPREV", "GX_CC_TEXC", "GX_CC_ZERO"}, scale,
                                 "Stage " + std::to_string(k) +
                                     ": trans = trans x albedo (the map in GX_TEXMAP2) x " +
                                     std::to_string(scale)));
    p.stages.back().frame_scale = TevStagePlan::FrameScale::Translucency;
  }
  const int k = static_cast<int>(p.stages.size());
  const int sd = 1 << last.color.scale.value();
  last.stage = GxConst<NameGroup::TevStage>::with_value(k);
  last.texcoord = texcoord;
  last.texmap = albedo.texture.map;
  last.color.in = {ColourIn{"GX_CC_ZERO"}, ColourIn{"GX_CC_RASC"}, ColourIn{"GX_CC_TEXC"},
                   last.color.in[3]};
  last.what = "Stage " + std::to_string(k) + ": out = (" + (adds_translucency ? "trans + " : "") +
              (last.channel.name() + 3) + " x albedo) x " + std::to_string(sd);
  p.stages.push_back(last);
}

}  // namespace lt::gx
