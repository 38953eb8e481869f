#include "advise/texture_advice.h"

#include <algorithm>
#include <map>
#include <tuple>

#include "advise/advise.h"
#include "advise/material_error.h"
#include "advise/variant_trials.h"
#include "budget/report.h"
#include "paths/gx/gx_variant.h"

namespace lt::advise {

namespace {

// A budget detail's number (0 when the report lacks it).
std::size_t budget_number(const budget::Report& report, const std::string& key) {
  for (const budget::Detail& d : report.details)
    if (d.key == key && d.number) return static_cast<std::size_t>(*d.number);
  return 0;
}

// The kinds of map a material samples, as gx_variant.h's :map= tells them apart.
struct MaterialMaps {
  bool grey = false, colour = false;
  std::string text;
};
MaterialMaps maps_of(const Material& m) {
  MaterialMaps out;
  auto add = [&](const TextureMap* map, const char* what) {
    if (!map) return;
    (map->grey ? out.grey : out.colour) = true;
    out.text +=
        (out.text.empty() ? "" : ", ") + std::string(map->grey ? "grey " : "colour ") + what;
  };
  add(m.translucency ? m.translucency->thickness_map.get() : nullptr, "thickness map");
  add(m.albedo_map.get(), "albedo map");
  return out;
}

// The :map= values a material's maps are tried in: the kind's list (both lists when it has both
// kinds: a grey format leaves the colour maps at their default and the other way round).
std::vector<std::string> formats_for_maps(const MaterialMaps& maps) {
  std::vector<std::string> out;
  auto add = [&](const auto& list) {
    for (const char* f : list)
      if (std::find(out.begin(), out.end(), f) == out.end()) out.push_back(f);
  };
  if (maps.grey) add(kGreyMapFormats);
  if (maps.colour) add(kColourMapFormats);
  return out;
}

// The pick's variant with the map and LUT formats set ("" leaves the pick's), through the
// variant's one parser.
std::string with_formats(const std::string& variant, const std::string& map,
                         const std::string& lut) {
  gx::GxVariant key = gx::parse_gx_variant(variant);
  if (!map.empty()) key.map_format = gx::parse_gx_variant("map=" + map).map_format;
  if (!lut.empty()) key.lut_format = gx::parse_gx_variant("lut-format=" + lut).lut_format;
  return gx::to_string(key);
}

}  // namespace

void add_texture_advice(Advice& a, const Scene& scene, const PathInfo& path,
                        const PathOptions& options, const std::string& profile) {
  if (!path.writes_fifo_log || path.name != "gx") return;
  if (!has_any_pick(a)) return;
  VariantTrials trials(scene, path, options, profile, a.width, a.height);
  for (MaterialAdvice& ma : a.materials) {
    if (!ma.pick) continue;
    const std::string& picked = a.candidates[*ma.pick].candidate.variant;
    const gx::GxVariant pick_key = gx::parse_gx_variant(picked);
    // A colour lobe ramp's LUT stays RGBA8 whatever :lut-format= says (lobe_lut.h): nothing to try.
    const Material& material = scene.materials[ma.index];
    const bool colour_ramp =
        material.translucency && material.translucency->ramp && !material.translucency->ramp->grey;
    const bool lut = pick_key.lobe == gx::GxVariant::Lobe::Lut && ma.translucent && !colour_ramp;
    const MaterialMaps maps = maps_of(material);
    if (maps.text.empty() && !lut) continue;
    TextureAdvice advice;
    advice.maps = maps.text.empty() ? "no map" : maps.text;
    // Every map format with the I8 LUT, then the other LUT formats with the map's default.
    std::vector<std::pair<std::string, std::string>> tried;
    const std::string lut_default = lut ? kLutFormats[0] : "";
    for (const std::string& f : formats_for_maps(maps)) tried.push_back({f, lut_default});
    if (tried.empty()) tried.push_back({"", lut_default});
    if (lut) {
      const std::string map_default = tried.front().first;
      for (size_t k = 1; k < std::size(kLutFormats); ++k)
        tried.push_back({map_default, kLutFormats[k]});
    }
    for (const auto& [map, lut_format] : tried) {
      TextureOption o;
      o.map_format = map;
      o.lut_format = lut_format;
      try {
        o.variant = with_formats(picked, map, lut_format);
      } catch (const InputError& e) {
        o.failed = e.what_only();
      }
      if (o.failed.empty()) {
        const VariantTrials::Trial& t = trials.trial(o.variant);
        o.failed = t.failed;
        o.texture_bytes = budget_number(t.budget, "texture_bytes");
        o.tlut_bytes = budget_number(t.budget, "tlut_bytes");
        o.tmem_bytes = budget_number(t.budget, "tmem_bytes");
        if (o.failed.empty()) {
          const Comparison c = trials.compare(t, ma.index);
          o.error = c.covered;
          o.non_finite = non_finite_pixels(c);
        }
      }
      const bool within = o.failed.empty() && o.non_finite == 0 &&
                          stat_of(o.error, a.options.stat) <= a.options.max_lsb;
      // Fewest MEM1 bytes, then fewest TMEM bytes, then the least error.
      auto rank = [&](const TextureOption& x) {
        return std::make_tuple(x.mem1_bytes(), x.tmem_bytes, stat_of(x.error, a.options.stat));
      };
      if (within && (!advice.pick || rank(o) < rank(advice.options[*advice.pick])))
        advice.pick = advice.options.size();
      advice.options.push_back(std::move(o));
    }
    ma.textures = std::move(advice);
  }
}

}  // namespace lt::advise
