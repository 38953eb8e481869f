#include "paths/gx/gx_variant.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <iterator>
#include <set>
#include <sstream>

#include "core/error.h"
#include "gx/xfb_copy.h"
#include "model/translucency.h"

namespace lt::gx {

namespace {

const char* kValid =
    "valid: t=vertex | t=texgen, each with an optional :lut=N (N = 2..1024) and "
    ":lut-format=FMT (i8, i4, ia4, ia8), or lobe=xf-spec; "
    "t=texgen and lobe=xf-spec with an optional :view=object; any of them with :colors=round, "
    ":lights=round-each, :map=FMT (rgba8, rgb565, rgb5a3, cmpr; i8, ia8, ia4, i4; ci4, ci8), "
    ":mip=lin | near with an optional :mip-bias=B (-4 <= B < 4) and :mip-lod=diagonal (or "
    ":mip-lod=edge), :wrap=repeat (or :wrap=clamp), "
    ":base=tev (or :base=xf), :out=xfb (or :out=efb), "
    ":coverage=console (or :coverage=dolphin), :light-range=D (D >= 0), the vertex storage "
    ":vtx=, :nrm=, :clr=, :uv= (e.g. :vtx=s16/auto:nrm=s8:clr=rgb565:uv=s16/auto) and "
    ":draw=direct | indexed | strips | list, :vat=N (the vertex format GX_VTXFMTN, N = 0..7)";

// The :draw= values, in GxVariant::Draw's order.
constexpr const char* kDrawNames[] = {"direct", "indexed", "strips", "list"};

// The :map= values and the formats they name (gx_variant.h).
struct MapFormatName {
  const char* name;
  TexFormat format;
};
constexpr MapFormatName kMapFormats[] = {
    {"rgba8", TexFormat::RGBA8}, {"rgb565", TexFormat::RGB565}, {"rgb5a3", TexFormat::RGB5A3},
    {"cmpr", TexFormat::CMPR},   {"i8", TexFormat::I8},         {"ia8", TexFormat::IA8},
    {"ia4", TexFormat::IA4},     {"i4", TexFormat::I4},         {"ci4", TexFormat::CI4},
    {"ci8", TexFormat::CI8}};

// The :lut-format= values (gx_variant.h): the grey formats, each holding the LUT's intensity.
constexpr MapFormatName kLutFormats[] = {
    {"i8", TexFormat::I8}, {"i4", TexFormat::I4}, {"ia4", TexFormat::IA4}, {"ia8", TexFormat::IA8}};

// Whether all of `text` reads as one number into `out`.
template <class T>
bool parses_whole(const std::string& text, T& out) {
  const auto r = std::from_chars(text.data(), text.data() + text.size(), out);
  return r.ec == std::errc() && r.ptr == text.data() + text.size();
}

bool is_storage_key(const std::string& key) {
  for (std::string_view k : kVertexStorageKeys)
    if (k == key) return true;
  return false;
}

}  // namespace

GxVariant parse_gx_variant(const std::string& text) {
  GxVariant v;
  std::set<std::string> seen;
  auto bad = [&](const std::string& why) {
    throw InputError("--variant", text, "gx: " + why + " (" + kValid + ")");
  };
  std::istringstream parts(text);
  for (std::string part; std::getline(parts, part, ':');) {
    const auto eq = part.find('=');
    if (eq == std::string::npos) bad("'" + part + "' is not key=value");
    const std::string key = part.substr(0, eq), value = part.substr(eq + 1);
    const bool first = seen.insert(key).second;
    // A two-valued axis: `value`, refused unless it is `a` or `b`.
    auto either = [&](const char* a, const char* b) {
      if (value != a && value != b) bad(key + "=" + value + " is not " + a + " or " + b);
      return value;
    };
    if (key == "t" && first) {
      if (value == "vertex") {
        v.t = GxVariant::TexCoord::Vertex;
      } else if (value == "texgen") {
        v.t = GxVariant::TexCoord::Texgen;
      } else {
        bad("t=" + value + " is not a texture-coordinate source");
      }
    } else if (key == "lut" && first) {
      int n = 0;
      // 1024 is the hardware's largest texture side [OGC gx.h L4263]; the texel-centre remap
      // needs two texels.
      if (!parses_whole(value, n) || n < 2 || n > 1024)
        bad("lut=" + value + " is not a LUT width of 2..1024 texels");
      v.lut_size = n;
    } else if (key == "lut-format" && first) {
      const auto named = std::find_if(std::begin(kLutFormats), std::end(kLutFormats),
                                      [&](const MapFormatName& m) { return value == m.name; });
      if (named == std::end(kLutFormats))
        bad("lut-format=" + value + " is not a LUT format (i8, i4, ia4, ia8)");
      if (named->format != TexFormat::I8) v.lut_format = named->format;
    } else if (key == "lobe" && first) {
      if (value == "xf-spec") {
        v.lobe = GxVariant::Lobe::XfSpec;
      } else if (value == "lut") {
        v.lobe = GxVariant::Lobe::Lut;
      } else {
        bad("lobe=" + value + " is not a lobe method");
      }
    } else if (key == "colors" && first) {
      v.round_colors = either("round", "trunc") == "round";
    } else if (key == "lights" && first) {
      v.round_each_light = either("round-each", "sum") == "round-each";
    } else if (key == "map" && first) {
      const auto named = std::find_if(std::begin(kMapFormats), std::end(kMapFormats),
                                      [&](const MapFormatName& m) { return value == m.name; });
      if (named == std::end(kMapFormats))
        bad("map=" + value +
            " is not a map format (rgba8, rgb565, rgb5a3, cmpr; i8, ia8, ia4, i4; ci4, ci8)");
      if (named->format != TexFormat::RGBA8 && named->format != TexFormat::I8)
        v.map_format = named->format;
    } else if (key == "mip" && first) {
      v.mip = either("lin", "near") == "lin" ? GxVariant::Mip::Linear : GxVariant::Mip::Near;
    } else if (key == "mip-bias" && first) {
      double b = 0;
      if (!parses_whole(value, b) || !std::isfinite(b) || b < -4 || b >= 4)
        bad("mip-bias=" + value + " is not a LOD bias of -4 <= B < 4 levels");
      v.mip_bias = b;
    } else if (key == "mip-lod" && first) {
      v.mip_diagonal = either("diagonal", "edge") == "diagonal";
    } else if (key == "wrap" && first) {
      v.map_repeat = either("repeat", "clamp") == "repeat";
    } else if (key == "out" && first) {
      v.out = either("efb", "xfb") == "xfb" ? GxVariant::Output::Xfb : GxVariant::Output::Efb;
    } else if (key == "coverage" && first) {
      v.coverage =
          either("dolphin", "console") == "console" ? CoverageRule::Console : CoverageRule::Dolphin;
    } else if (key == "base" && first) {
      v.base_in_tev = either("tev", "xf") == "tev";
    } else if (key == "light-range" && first) {
      double d = 0;
      if (!parses_whole(value, d) || !std::isfinite(d) || d < 0)
        bad("light-range=" + value + " is not a distance >= 0");
      v.light_range = d;
    } else if (key == "view" && first) {
      v.view_object = either("object", "exact") == "object";
    } else if (key == "draw" && first) {
      const auto named = std::find(std::begin(kDrawNames), std::end(kDrawNames), value);
      if (named == std::end(kDrawNames))
        bad("draw=" + value + " is not a way of sending vertices (direct, indexed, strips, list)");
      v.draw = static_cast<GxVariant::Draw>(named - std::begin(kDrawNames));
    } else if (key == "vat" && first) {
      // GX_VTXFMT0..7: the draw command's three low bits [OGC gx.h GX_MAXVTXFMT 8].
      if (!parses_whole(value, v.vat) || v.vat < 0 || v.vat > 7)
        bad("vat=" + value + " is not a vertex format number (0..7: GX_VTXFMT0..7)");
    } else if (is_storage_key(key) && first) {
      try {
        set_vertex_storage(v.storage, key, value, "--variant");
      } catch (const InputError& e) {
        bad(key + "=" + value + ": " + e.what_only());
      }
    } else {
      bad("'" + key + "' is not a gx variant axis, or is given twice");
    }
  }
  if (text.empty()) bad("empty variant");
  if (seen.count("mip-bias") && v.mip == GxVariant::Mip::Off)
    bad("mip-bias= biases the LOD of mipmapped maps: give :mip=lin or :mip=near");
  if (seen.count("mip-lod") && v.mip == GxVariant::Mip::Off)
    bad("mip-lod= chooses how mipmapped maps take their LOD: give :mip=lin or :mip=near");
  if (v.lobe == GxVariant::Lobe::XfSpec &&
      (seen.count("t") || seen.count("lut") || seen.count("lut-format")))
    bad("lobe=xf-spec uses no texture, so it takes no t=, lut= or lut-format=");
  // t=vertex computes V and L exactly per vertex on the CPU: a per-object view would only lose.
  // lobe=xf-spec has no LUT stage to fold the base into.
  if (v.base_in_tev && v.lobe == GxVariant::Lobe::XfSpec)
    bad("base=tev folds the base into the LUT stage; lobe=xf-spec has none");
  if (v.view_object && v.lobe == GxVariant::Lobe::Lut && v.t == GxVariant::TexCoord::Vertex)
    bad("view=object is for t=texgen and lobe=xf-spec (t=vertex has the exact V per vertex)");
  return v;
}

std::string to_string(const GxVariant& v) {
  std::string s;
  if (v.lobe == GxVariant::Lobe::XfSpec) {
    s = "lobe=xf-spec";
  } else {
    s = v.t == GxVariant::TexCoord::Vertex ? "t=vertex" : "t=texgen";
    if (v.lut_size != kDefaultLutSize) s += ":lut=" + std::to_string(v.lut_size);
    if (v.lut_format) {
      for (const MapFormatName& m : kLutFormats)
        if (m.format == *v.lut_format) s += std::string(":lut-format=") + m.name;
    }
  }
  if (v.view_object) s += ":view=object";
  if (v.base_in_tev) s += ":base=tev";
  if (v.round_colors) s += ":colors=round";
  if (v.round_each_light) s += ":lights=round-each";
  if (v.map_format) {
    for (const MapFormatName& m : kMapFormats)
      if (m.format == *v.map_format) s += std::string(":map=") + m.name;
  }
  if (v.mip != GxVariant::Mip::Off) s += v.mip == GxVariant::Mip::Linear ? ":mip=lin" : ":mip=near";
  if (v.mip_bias != 0) {
    char buf[32];
    const auto r = std::to_chars(buf, buf + sizeof buf, v.mip_bias);
    s += ":mip-bias=" + std::string(buf, r.ptr);
  }
  if (v.mip_diagonal) s += ":mip-lod=diagonal";
  if (v.map_repeat) s += ":wrap=repeat";
  if (v.out == GxVariant::Output::Xfb) s += ":out=xfb";
  if (v.coverage == CoverageRule::Console) s += ":coverage=console";
  if (v.light_range) {
    // The shortest text that reads back as the same double (a sweep row builds by its name).
    char buf[32];
    const auto r = std::to_chars(buf, buf + sizeof buf, *v.light_range);
    s += ":light-range=" + std::string(buf, r.ptr);
  }
  // Each attribute stored otherwise than the default F32 stream, in the storage key's order.
  const VertexStorage f32;
  for (std::string_view k : kVertexStorageKeys) {
    const std::string value = vertex_storage_value(v.storage, k);
    if (value != vertex_storage_value(f32, k)) s += ":" + std::string(k) + "=" + value;
  }
  if (v.draw != GxVariant::Draw::Direct)
    s += std::string(":draw=") + kDrawNames[static_cast<int>(v.draw)];
  if (v.vat != 0) s += ":vat=" + std::to_string(v.vat);
  return s;
}

bool is_grey_map_format(TexFormat format) {
  return format == TexFormat::I4 || format == TexFormat::IA4 || format == TexFormat::I8 ||
         format == TexFormat::IA8;
}

TexFormat map_texture_format(const GxVariant& v, bool grey_map) {
  // A colour-indexed format takes either kind: its TLUT's format follows the map (map_tlut_format).
  if (v.map_format && (is_indexed(*v.map_format) || is_grey_map_format(*v.map_format) == grey_map))
    return *v.map_format;
  return grey_map ? TexFormat::I8 : TexFormat::RGBA8;
}

TlutFormat map_tlut_format(bool grey_map) {
  return grey_map ? TlutFormat::IA8 : TlutFormat::RGB565;
}

std::string refusal(const Scene& scene, const GxVariant& v) {
  // At the scene's size; the path checks a --width/--height override again when it is built.
  if (v.out == GxVariant::Output::Xfb) {
    std::string why = xfb_size_refusal(scene.width, scene.height);
    if (!why.empty()) return "out=xfb: " + why;
  }
  if (v.lobe == GxVariant::Lobe::XfSpec) {
    for (const Material& m : scene.materials) {
      if (m.translucency && m.translucency->ramp)
        return "lobe=xf-spec fits t^power in the XF, but material " + m.name +
               "'s lobe is a ramp (a table): use t=vertex or t=texgen";
    }
  }
  // A stored mesh sends its normals in object space (scene_vertices.h); t=texgen's texture
  // matrix is built for the world-space normals of the F32 stream.
  if (!v.storage.is_default() && v.lobe == GxVariant::Lobe::Lut &&
      v.t == GxVariant::TexCoord::Texgen)
    return "t=texgen reads the normal through a texture matrix for world-space normals; a stored "
           "mesh (:vtx=, :nrm=, :clr=, :uv=) sends them in object space: use t=vertex";
  if (v.lobe == GxVariant::Lobe::Lut && v.t == GxVariant::TexCoord::Vertex) return "";
  for (const Material& m : scene.materials) {
    // view=object makes V and L constant per object whatever the camera and lights; a
    // normalised H is still not affine in the normal.
    if (v.view_object) {
      if (m.translucency && m.translucency->normalize_distorted_light)
        return to_string(v) + " needs t affine in the normal: material " + m.name +
               " normalises H; use t=vertex";
      continue;
    }
    const std::string why = model::why_t_is_not_affine_in_the_normal(scene, m);
    if (!why.empty())
      return to_string(v) + " needs t affine in the normal: " + why + "; use t=vertex";
  }
  return "";
}

}  // namespace lt::gx
