#include "advise/advise_output.h"

#include <algorithm>
#include <sstream>

#include "core/file_name.h"
#include "core/fixed.h"
#include "core/fs.h"
#include "paths/gx/c_exporter.h"
#include "paths/gx/gx_budget.h"
#include "paths/gx/gx_path.h"
#include "render/session.h"

namespace lt::advise {

namespace {

std::string cost_text(const Cost& c) {
  return fixed(c.ops, 0) + " ops" +
         (c.texture_bytes > 0 ? " + " + fixed(c.texture_bytes, 0) + " B" : "");
}

// The figures, then the pixels over 1 LSB split: a max that is edge shifts (a silhouette the
// reference's rasteriser places elsewhere) reads apart from a shading error.
std::string error_text(const ErrorStats& e, const EdgeShiftSplit& split) {
  return "max " + fixed(e.max_lsb, 2) + ", p99 " + fixed(e.p99_lsb, 2) + ", mean " +
         fixed(e.mean_lsb, 2) + " (shading max " + fixed(split.shading_max_lsb, 2) + ", " +
         std::to_string(split.edge_shift_pixels) + " edge shifts > 1 LSB)";
}

// A storage's name as the text shows it.
std::string storage_label(const StorageOption& o) {
  return o.storage.empty() ? "F32 direct (the default)" : o.storage;
}

// The vertex storage advised for a material and what each tried storage measured.
void storage_text(std::ostream& out, const StorageAdvice& s, Stat stat) {
  if (s.pick) {
    const StorageOption& p = s.options[*s.pick];
    out << "  storage: " << storage_label(p) << ": " << p.bytes.fifo_bytes
        << " FIFO bytes a frame, " << p.bytes.mem1_bytes() << " MEM1 bytes, " << to_string(stat)
        << " " << fixed(stat_of(p.error, stat), 2) << " LSB (rendered)\n";
  } else {
    out << "  storage: none within the budget\n";
  }
  for (const StorageOption& o : s.options) {
    out << "    " << (s.pick && &s.options[*s.pick] == &o ? "* " : "  ") << storage_label(o)
        << ": ";
    if (!o.failed.empty()) {
      out << o.failed << "\n";
      continue;
    }
    out << o.bytes.vertex_bytes << " B a vertex, " << o.bytes.fifo_bytes << " FIFO B, "
        << o.bytes.mem1_bytes() << " MEM1 B, " << o.bytes.xf_vertices << " XF vertices; max "
        << fixed(o.error.max_lsb, 2) << ", p99 " << fixed(o.error.p99_lsb, 2) << ", mean "
        << fixed(o.error.mean_lsb, 2)
        << (o.non_finite ? ", " + std::to_string(o.non_finite) + " non-finite pixels" : "") << "\n";
  }
}

nlohmann::ordered_json storage_json(const StorageAdvice& s) {
  nlohmann::ordered_json j;
  j["pick"] =
      s.pick ? nlohmann::ordered_json(s.options[*s.pick].storage) : nlohmann::ordered_json(nullptr);
  j["options"] = nlohmann::ordered_json::array();
  for (const StorageOption& o : s.options) {
    nlohmann::ordered_json jo;
    jo["storage"] = o.storage;
    jo["variant"] = o.variant;
    jo["failed"] = o.failed;
    if (o.failed.empty()) {
      for (const auto& [name, field] : ConsoleBytes::kFields) jo[name] = o.bytes.*field;
      jo["mem1_bytes"] = o.bytes.mem1_bytes();
      jo["error"] = {
          {"max", o.error.max_lsb}, {"p99", o.error.p99_lsb}, {"mean", o.error.mean_lsb}};
      jo["non_finite_pixels"] = o.non_finite;
    }
    j["options"].push_back(jo);
  }
  return j;
}

// A texture option's formats as the text shows them: "map ci4, LUT i8".
std::string texture_label(const TextureOption& o) {
  std::string s;
  if (!o.map_format.empty()) s = "map " + o.map_format;
  if (!o.lut_format.empty()) s += (s.empty() ? "LUT " : ", LUT ") + o.lut_format;
  return s;
}

// The texture formats advised for a material and what each tried format measured.
void textures_text(std::ostream& out, const TextureAdvice& t, Stat stat) {
  if (t.pick) {
    const TextureOption& p = t.options[*t.pick];
    out << "  textures (" << t.maps << "): " << texture_label(p) << ": " << p.mem1_bytes()
        << " MEM1 bytes (" << p.texture_bytes << " texels + " << p.tlut_bytes << " TLUT), "
        << p.tmem_bytes << " TMEM bytes, " << to_string(stat) << " "
        << fixed(stat_of(p.error, stat), 2) << " LSB (rendered: " << p.variant << ")\n";
  } else {
    out << "  textures (" << t.maps << "): none within the budget\n";
  }
  for (const TextureOption& o : t.options) {
    out << "    " << (t.pick && &t.options[*t.pick] == &o ? "* " : "  ") << texture_label(o)
        << ": ";
    if (!o.failed.empty()) {
      out << o.failed << "\n";
      continue;
    }
    out << o.mem1_bytes() << " MEM1 B (" << o.tlut_bytes << " TLUT), " << o.tmem_bytes
        << " TMEM B; max " << fixed(o.error.max_lsb, 2) << ", p99 " << fixed(o.error.p99_lsb, 2)
        << ", mean " << fixed(o.error.mean_lsb, 2)
        << (o.non_finite ? ", " + std::to_string(o.non_finite) + " non-finite pixels" : "") << "\n";
  }
}

nlohmann::ordered_json textures_json(const TextureAdvice& t) {
  nlohmann::ordered_json j;
  j["maps"] = t.maps;
  auto format_or_null = [](const std::string& f) {
    return f.empty() ? nlohmann::ordered_json(nullptr) : nlohmann::ordered_json(f);
  };
  j["pick"] = nullptr;
  if (t.pick) {
    const TextureOption& p = t.options[*t.pick];
    j["pick"] = {{"map_format", format_or_null(p.map_format)},
                 {"lut_format", format_or_null(p.lut_format)},
                 {"variant", p.variant},
                 {"mem1_bytes", p.mem1_bytes()},
                 {"tmem_bytes", p.tmem_bytes}};
  }
  j["options"] = nlohmann::ordered_json::array();
  for (const TextureOption& o : t.options) {
    nlohmann::ordered_json jo;
    jo["map_format"] = format_or_null(o.map_format);
    jo["lut_format"] = format_or_null(o.lut_format);
    jo["variant"] = o.variant;
    jo["failed"] = o.failed;
    if (o.failed.empty()) {
      jo["texture_bytes"] = o.texture_bytes;
      jo["tlut_bytes"] = o.tlut_bytes;
      jo["mem1_bytes"] = o.mem1_bytes();
      jo["tmem_bytes"] = o.tmem_bytes;
      jo["error"] = {
          {"max", o.error.max_lsb}, {"p99", o.error.p99_lsb}, {"mean", o.error.mean_lsb}};
      jo["non_finite_pixels"] = o.non_finite;
    }
    j["options"].push_back(jo);
  }
  return j;
}

// How the pick compares with the path's default for one material.
std::string against_default(const Advice& a, size_t m, size_t pick) {
  const CandidateResult& d = a.candidates.front();
  const CandidateResult& p = a.candidates[pick];
  if (pick == 0) return "the pick is the default";
  if (!d.rendered)
    return "the default " + a.default_variant + " was not rendered (" +
           (d.over_profile.empty() ? d.refused : d.over_profile) + ")";
  const double saved = d.cost[m].ops - p.cost[m].ops;
  const double pct = d.cost[m].ops > 0 ? 100.0 * saved / d.cost[m].ops : 0.0;
  return "default " + a.default_variant + ": " + cost_text(d.cost[m]) + ", " +
         error_text(d.error[m], d.edge_split[m]) + "; the pick saves " + fixed(saved, 0) +
         " ops (" + fixed(pct, 1) + "%) and " +
         fixed(d.cost[m].texture_bytes - p.cost[m].texture_bytes, 0) + " texture bytes";
}

nlohmann::ordered_json error_summary_json(const ErrorStats& e, const EdgeShiftSplit& split) {
  return {{"max", e.max_lsb},
          {"p99", e.p99_lsb},
          {"mean", e.mean_lsb},
          {"shading_max", split.shading_max_lsb},
          {"edge_shift_pixels", split.edge_shift_pixels},
          {"shading_pixels", split.shading_pixels}};
}

// The program files one kind of built stage is written as.
const char* extension_of(const std::string& kind) {
  if (kind == "arb-fragment") return ".fp";
  if (kind == "arb-vertex") return ".vp";
  if (kind == "combiners") return ".comb";
  return nullptr;
}

}  // namespace

std::string to_text(const Advice& a) {
  std::ostringstream out;
  const AdviseOptions& o = a.options;
  out << "advise: " << o.scene_file.string() << " on " << o.profile << " (path " << a.path
      << "), budget " << fixed(o.max_lsb, 2) << " LSB " << to_string(o.stat) << ", " << a.width
      << "x" << a.height << "\n";
  size_t pruned = 0, excluded = 0;
  for (const CandidateResult& c : a.candidates) {
    pruned += c.pruned.empty() ? 0 : 1;
    excluded += (c.refused.empty() && c.over_profile.empty()) ? 0 : 1;
  }
  out << "  " << a.candidates.size() << " candidates: " << a.rendered() << " rendered, " << pruned
      << " pruned, " << excluded << " excluded (refused or over " << o.profile << "); "
      << fixed(a.seconds, 1) << " s\n";
  for (const MaterialAdvice& ma : a.materials) {
    const size_t m = ma.index;
    out << "\nmaterial " << ma.name << " (" << fixed(ma.pixels, 0) << " pixels, "
        << fixed(ma.vertices, 0) << " vertices" << (ma.translucent ? "" : ", no translucency")
        << ")\n";
    if (ma.pick) {
      const CandidateResult& p = a.candidates[*ma.pick];
      out << "  pick: " << p.candidate.variant << ": " << cost_text(p.cost[m]) << ", "
          << error_text(p.error[m], p.edge_split[m]) << "\n  " << against_default(a, m, *ma.pick)
          << "\n";
      if (ma.storage) storage_text(out, *ma.storage, o.stat);
      if (ma.textures) textures_text(out, *ma.textures, o.stat);
    } else if (ma.closest) {
      const CandidateResult& c = a.candidates[*ma.closest];
      out << "  no candidate within the budget; closest: " << c.candidate.variant << ": "
          << cost_text(c.cost[m]) << ", " << error_text(c.error[m], c.edge_split[m]) << "\n";
    } else {
      out << "  no candidate within the budget, and none renders without a non-finite pixel\n";
    }
    if (ma.refinement) {
      const Refinement& r = *ma.refinement;
      out << "  mesh refinement with " << a.candidates[r.candidate].candidate.variant
          << " (vertices: " << to_string(o.stat) << " LSB):\n";
      for (const auto& [name, steps] :
           {std::pair{"adaptive", &r.adaptive}, std::pair{"uniform", &r.uniform}}) {
        out << "    " << name << ":";
        for (const RefinementStep& s : *steps)
          out << " " << s.vertices << ": " << fixed(stat_of(s.error, o.stat), 2);
        out << "\n";
      }
      for (size_t i : r.tried)
        out << "    tried first, stalled over the budget: " << a.candidates[i].candidate.variant
            << "\n";
      if (r.holds_at) {
        out << "  pick: " << a.candidates[r.candidate].candidate.variant << " on a refined mesh, +"
            << r.vertices_added()
            << " vertices: " << error_text(r.pick_step().error, r.pick_step().edge_split) << "\n";
      }
    }
    out << "  front (cost against " << to_string(o.stat) << " error):\n";
    for (size_t i : ma.front) {
      const CandidateResult& c = a.candidates[i];
      out << "    " << (ma.pick && *ma.pick == i ? "* " : "  ") << c.candidate.variant << ": "
          << cost_text(c.cost[m]) << ", " << error_text(c.error[m], c.edge_split[m]) << "\n";
    }
    std::string hard;
    for (const HardCase& h : ma.hard_cases)
      hard += (hard.empty() ? "" : ", ") + h.file.stem().string();
    out << "  hard cases reached: " << (hard.empty() ? "none" : hard) << "\n";
    for (const CandidateResult& c : a.candidates) {
      const std::string why = c.hard_failure(m);
      if (!why.empty()) out << "  excluded " << c.candidate.variant << ": " << why << "\n";
      if (c.rendered && c.non_finite[m] > 0)
        out << "  excluded " << c.candidate.variant << ": " << c.non_finite[m]
            << " non-finite pixels on the scene\n";
    }
  }
  bool header = false;
  for (const CandidateResult& c : a.candidates) {
    const std::string why = !c.refused.empty()        ? "refused: " + c.refused
                            : !c.over_profile.empty() ? "over the profile: " + c.over_profile
                                                      : "";
    if (why.empty()) continue;
    if (!header) out << "\nexcluded before rendering:\n";
    header = true;
    out << "  " << c.candidate.variant << ": " << why << "\n";
  }
  // Pruned candidates grouped by the reason (one reason often prunes dozens).
  std::vector<std::pair<std::string, std::vector<std::string>>> groups;
  for (const CandidateResult& c : a.candidates) {
    if (c.pruned.empty()) continue;
    const std::string reason = c.candidate.never_cheaper.empty()
                                   ? c.pruned
                                   : "the same image as the variant without "
                                     ":guards=all, from more instructions "
                                     "(arb_guards.h)";
    auto g = std::find_if(groups.begin(), groups.end(),
                          [&](const auto& x) { return x.first == reason; });
    if (g == groups.end()) g = groups.insert(groups.end(), {reason, {}});
    g->second.push_back(c.candidate.variant);
  }
  if (!groups.empty()) out << "\npruned (not rendered):\n";
  for (const auto& [reason, names] : groups) {
    std::string list;
    for (const std::string& n : names) list += (list.empty() ? "" : " ") + n;
    out << "  " << names.size() << ": " << reason << ":\n    " << list << "\n";
  }
  out << "\nnot searched:\n";
  for (const std::string& l : a.left_out) out << "  " << l << "\n";
  return out.str();
}

nlohmann::ordered_json to_json(const Advice& a) {
  const AdviseOptions& o = a.options;
  nlohmann::ordered_json j;
  j["scene"] = o.scene_file.string();
  j["target"] = o.profile;
  j["path"] = a.path;
  j["default"] = a.default_variant;
  j["budget"] = {{"max_lsb", o.max_lsb}, {"stat", to_string(o.stat)}};
  j["width"] = a.width;
  j["height"] = a.height;
  j["exhaustive"] = o.exhaustive;
  j["seconds"] = a.seconds;
  j["rendered"] = a.rendered();
  j["materials"] = nlohmann::ordered_json::array();
  for (const MaterialAdvice& ma : a.materials) {
    const size_t m = ma.index;
    nlohmann::ordered_json jm;
    jm["name"] = ma.name;
    jm["pixels"] = ma.pixels;
    jm["vertices"] = ma.vertices;
    auto name_of = [&](const std::optional<size_t>& i) -> nlohmann::ordered_json {
      if (!i) return nullptr;
      return a.candidates[*i].candidate.variant;
    };
    jm["pick"] = name_of(ma.pick);
    jm["closest"] = name_of(ma.closest);
    if (ma.storage) jm["storage"] = storage_json(*ma.storage);
    if (ma.textures) jm["textures"] = textures_json(*ma.textures);
    if (ma.refinement) {
      const Refinement& r = *ma.refinement;
      auto steps = [&](const std::vector<RefinementStep>& v) {
        nlohmann::ordered_json out = nlohmann::ordered_json::array();
        for (const RefinementStep& s : v)
          out.push_back({{"vertices", s.vertices},
                         {"error", error_summary_json(s.error, s.edge_split)},
                         {"non_finite_pixels", s.non_finite}});
        return out;
      };
      nlohmann::ordered_json tried = nlohmann::ordered_json::array();
      for (size_t i : r.tried) tried.push_back(a.candidates[i].candidate.variant);
      jm["refinement"] = {{"variant", a.candidates[r.candidate].candidate.variant},
                          {"tried", tried},
                          {"adaptive", steps(r.adaptive)},
                          {"uniform", steps(r.uniform)},
                          {"holds_at", r.holds_at ? nlohmann::ordered_json(*r.holds_at)
                                                  : nlohmann::ordered_json(nullptr)}};
    }
    jm["front"] = nlohmann::ordered_json::array();
    for (size_t i : ma.front) jm["front"].push_back(a.candidates[i].candidate.variant);
    jm["hard_cases"] = nlohmann::ordered_json::array();
    for (const HardCase& h : ma.hard_cases)
      jm["hard_cases"].push_back({{"scene", h.file.stem().string()}, {"reached_by", h.reached_by}});
    jm["candidates"] = nlohmann::ordered_json::array();
    for (const CandidateResult& c : a.candidates) {
      nlohmann::ordered_json jc;
      jc["variant"] = c.candidate.variant;
      jc["ops"] = c.cost[m].ops;
      jc["texture_bytes"] = c.cost[m].texture_bytes;
      jc["rendered"] = c.rendered;
      jc["error"] = c.rendered ? error_summary_json(c.error[m], c.edge_split[m])
                               : nlohmann::ordered_json(nullptr);
      jc["non_finite_pixels"] = c.non_finite[m];
      jc["refused"] = c.refused;
      jc["over_profile"] = c.over_profile;
      jc["pruned"] = c.pruned;
      if (c.hard[m]) {
        jc["hard_cases"] = nlohmann::ordered_json::array();
        for (const HardResult& h : *c.hard[m])
          jc["hard_cases"].push_back({{"scene", h.scene},
                                      {"non_finite_pixels", h.non_finite_pixels},
                                      {"max_lsb", h.max_lsb}});
      } else {
        jc["hard_cases"] = nullptr;
      }
      jm["candidates"].push_back(jc);
    }
    j["materials"].push_back(jm);
  }
  j["not_searched"] = a.left_out;
  return j;
}

std::vector<std::string> write_programs(const Advice& a, const Scene& scene,
                                        const std::filesystem::path& dir) {
  std::vector<std::string> written;
  const PathInfo& path = find_path(a.path);
  for (const MaterialAdvice& ma : a.materials) {
    // The pick, or the variant of a refinement that holds (its error the refined mesh's).
    const bool refined = !ma.pick && ma.refinement && ma.refinement->holds_at;
    if (!ma.pick && !refined) continue;
    const CandidateResult& p = a.candidates[refined ? ma.refinement->candidate : *ma.pick];
    const ErrorStats& error =
        refined ? ma.refinement->adaptive[*ma.refinement->holds_at].error : p.error[ma.index];
    const std::string base = file_name_safe(ma.name);
    if (a.path == "gx") {
      // export's C for the scene under the picked variant, its figures the material's: the
      // material's pass functions are those named for it (ltrender_<material>_pass<N>).
      const gx::GxVariant v = gx::parse_gx_variant(p.candidate.variant);
      gx::ExportFigures f;
      f.scene = a.options.scene_file.string();
      f.variant = p.candidate.variant;
      f.width = a.width;
      f.height = a.height;
      f.error = error;
      f.budget =
          budget::to_text(gx::gx_budget_scene(scene, p.candidate.variant, a.options.profile));
      written.push_back(base + ".c");
      write_text_file(dir / written.back(), gx::export_c(gx::scene_programs_for(scene, v, ""), f));
      continue;
    }
    // The built stages of the material: ARB programs or combiner files, one file each.
    RenderSession session(scene, a.width, a.height);
    PathOptions options;
    if (path.takes_profile) options.profile = a.options.profile;
    const auto built = session.build(path, p.candidate.variant, options);
    const std::string prefix = "material " + ma.name;
    int n = 0;
    for (const BuiltStage& s : built->stages()) {
      const char* ext = extension_of(s.kind);
      if (!ext || s.source.empty() || s.name.rfind(prefix, 0) != 0) continue;
      if (s.name.size() > prefix.size() && s.name[prefix.size()] != ':' &&
          s.name[prefix.size()] != ',')
        continue;  // another material whose name starts with this one's
      written.push_back(base + "_" + std::to_string(n++) + ext);
      write_text_file(dir / written.back(), s.source);
    }
  }
  return written;
}

}  // namespace lt::advise
