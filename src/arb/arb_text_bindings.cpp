#include "arb/arb_text_bindings.h"

#include <initializer_list>

namespace lt::arbfp::text {

namespace {

std::string list(std::initializer_list<const char*> names) {
  std::string s;
  for (const char* n : names) s += (s.empty() ? "" : ", ") + std::string(n);
  return s;
}

// "." then one of `names`; the name taken.
std::string dot_choice(Cursor& c, std::initializer_list<const char*> names,
                       const std::string& what) {
  c.expect(".", what + " (." + list(names) + ")");
  const Token& t = c.peek();
  for (const char* n : names) {
    if (t.is(n)) return c.take().text;
  }
  c.expected(what + " (" + list(names) + ")");
}

// "." then one of `names` when the next two tokens are that; empty otherwise (the dot may start
// a swizzle or a mask instead).
std::string optional_dot_choice(Cursor& c, std::initializer_list<const char*> names) {
  if (!c.peek().is(".")) return "";
  for (const char* n : names) {
    if (c.peek(1).is(n)) {
      c.take();
      return c.take().text;
    }
  }
  return "";
}

// "[n]", required.
int bracket_index(Cursor& c, int limit, const std::string& what) {
  c.expect("[", "'[' and " + what);
  const int n = c.expect_index(limit, what);
  c.expect("]");
  return n;
}

// "[n]" if present, else `fallback`.
int optional_bracket_index(Cursor& c, int limit, const std::string& what, int fallback) {
  return c.peek().is("[") ? bracket_index(c, limit, what) : fallback;
}

std::string indexed(const std::string& base, int n) {
  return base + "[" + std::to_string(n) + "]";
}

ParamSlot binding_slot(const std::string& key) {
  ParamSlot s;
  s.binding = key;
  return s;
}

// "[a]" or "[a..b]" (when `ranges`) into [first, last].
void index_range(Cursor& c, int limit, const std::string& what, bool ranges, int& first,
                 int& last) {
  c.expect("[", "'[' and " + what);
  first = last = c.expect_index(limit, what);
  if (ranges && c.peek().is("..")) {
    c.take();
    const Position at = c.peek().at;
    last = c.expect_index(limit, what);
    if (last < first) Cursor::fail_at(at, "expected a range end >= " + std::to_string(first));
  }
  c.expect("]", ranges ? "']' or '..'" : "']'");
}

// state.matrix.<name>[.inverse|.transpose|.invtrans][.row[a] | .row[a..b]]
std::vector<ParamSlot> matrix_binding(Cursor& c, const Limits& limits, bool ranges) {
  const Position at = c.peek(1).at;
  std::string m = "state.matrix." +
                  dot_choice(c, {"modelview", "projection", "mvp", "texture", "palette", "program"},
                             "a matrix");
  if (m == "state.matrix.palette") {
    Cursor::fail_at(at, "expected a matrix Mesa supports (ARB_matrix_palette is not)");
  }
  if (m == "state.matrix.modelview") {
    // modelview[n > 0] is ARB_vertex_blend's, which Mesa lacks.
    m = indexed(m, optional_bracket_index(c, 1, "the modelview matrix 0 (no ARB_vertex_blend)", 0));
  } else if (m == "state.matrix.texture") {
    m = indexed(m, optional_bracket_index(c, limits.texture_coords, "a texture unit", 0));
  } else if (m == "state.matrix.program") {
    m = indexed(m, bracket_index(c, limits.program_matrices, "a program matrix"));
  }
  const std::string modifier = optional_dot_choice(c, {"inverse", "transpose", "invtrans"});
  if (!modifier.empty()) m += "." + modifier;
  int first = 0, last = 3;
  if (c.peek().is(".") && c.peek(1).is("row")) {
    c.take();
    c.take();
    index_range(c, 4, "a matrix row", ranges, first, last);
  } else if (!ranges) {
    c.fail("expected .row[n]: a whole matrix is four parameter slots, one is allowed here");
  }
  std::vector<ParamSlot> out;
  for (int r = first; r <= last; ++r)
    out.push_back(binding_slot(m + ".row[" + std::to_string(r) + "]"));
  return out;
}

std::string state_binding(Cursor& c, ProgramKind kind, const Limits& limits) {
  const bool vertex = kind == ProgramKind::Vertex;
  const Position at = c.peek(1).at;
  const std::string group = dot_choice(c,
                                       {"material", "light", "lightmodel", "lightprod", "texgen",
                                        "fog", "clip", "point", "texenv", "depth", "matrix"},
                                       "a state binding");
  auto only = [&](bool allowed, const char* which) {
    if (!allowed) {
      Cursor::fail_at(at, std::string("expected a state binding of ") + which +
                              " programs here: state." + group + " is not one");
    }
  };
  std::string s = "state." + group;
  if (group == "material") {
    const std::string face = optional_dot_choice(c, {"front", "back"});
    s.append(".").append((face.empty() ? "front" : face) + "." +
                         dot_choice(c, {"ambient", "diffuse", "specular", "emission", "shininess"},
                                    "a material property"));
  } else if (group == "light") {
    s = indexed(s, bracket_index(c, limits.lights, "a light number"));
    const std::string p =
        dot_choice(c, {"ambient", "diffuse", "specular", "position", "attenuation", "spot", "half"},
                   "a light property");
    s.append(".").append(p);
    if (p == "spot") s.append(".").append(dot_choice(c, {"direction"}, "the spot direction"));
  } else if (group == "lightmodel") {
    const std::string p =
        dot_choice(c, {"ambient", "scenecolor", "front", "back"}, "a light model property");
    if (p == "front" || p == "back") {
      s.append(".").append(p + "." + dot_choice(c, {"scenecolor"}, "the scene colour"));
    } else {
      s += p == "scenecolor" ? ".front.scenecolor" : ".ambient";
    }
  } else if (group == "lightprod") {
    s = indexed(s, bracket_index(c, limits.lights, "a light number"));
    const std::string face = optional_dot_choice(c, {"front", "back"});
    s.append(".").append((face.empty() ? "front" : face) + "." +
                         dot_choice(c, {"ambient", "diffuse", "specular"}, "a light product"));
  } else if (group == "texgen") {
    only(vertex, "vertex");
    s = indexed(s, optional_bracket_index(c, limits.texture_coords, "a texture unit", 0));
    s.append(".").append(dot_choice(c, {"eye", "object"}, "a texgen plane"));
    s.append(".").append(dot_choice(c, {"s", "t", "r", "q"}, "a texgen coordinate"));
  } else if (group == "fog") {
    s.append(".").append(dot_choice(c, {"color", "params"}, "a fog property"));
  } else if (group == "clip") {
    only(vertex, "vertex");
    s = indexed(s, bracket_index(c, limits.clip_planes, "a clip plane"));
    s.append(".").append(dot_choice(c, {"plane"}, "the clip plane"));
  } else if (group == "point") {
    only(vertex, "vertex");
    s.append(".").append(dot_choice(c, {"size", "attenuation"}, "a point property"));
  } else if (group == "texenv") {
    only(!vertex, "fragment");
    s = indexed(s, optional_bracket_index(c, limits.texture_image_units, "a texture unit", 0));
    s.append(".").append(dot_choice(c, {"color"}, "the texture environment colour"));
  } else if (group == "depth") {
    only(!vertex, "fragment");
    s.append(".").append(dot_choice(c, {"range"}, "the depth range"));
  }
  return s;
}

}  // namespace

std::string parse_attrib_binding(Cursor& c, ProgramKind kind, const Limits& limits) {
  const bool vertex = kind == ProgramKind::Vertex;
  const std::string root = vertex ? "vertex" : "fragment";
  if (!c.peek().is(root.c_str())) c.expected("a " + root + ".* input");
  c.take();
  const Position at = c.peek(1).at;
  const std::string p =
      vertex ? dot_choice(c,
                          {"position", "weight", "normal", "color", "fogcoord", "texcoord",
                           "matrixindex", "attrib"},
                          "a vertex attribute")
             : dot_choice(c, {"color", "texcoord", "fogcoord", "position"}, "a fragment attribute");
  if (p == "weight" || p == "matrixindex") {
    Cursor::fail_at(at, "expected a vertex attribute Mesa supports (vertex." + p + " is " +
                            (p == "weight" ? "ARB_vertex_blend's" : "ARB_matrix_palette's") + ")");
  }
  if (p == "color") {
    const std::string which = optional_dot_choice(c, {"primary", "secondary"});
    return root + ".color." + (which.empty() ? "primary" : which);
  }
  if (p == "texcoord") {
    return indexed(root + ".texcoord",
                   optional_bracket_index(c, limits.texture_coords, "a texture coordinate", 0));
  }
  if (p == "attrib") {
    return indexed("vertex.attrib", bracket_index(c, limits.vertex_attribs, "a generic attribute"));
  }
  return root + "." + p;
}

std::string parse_result_binding(Cursor& c, ProgramKind kind, const Limits& limits,
                                 bool draw_buffers) {
  c.expect("result");
  if (kind == ProgramKind::Fragment) {
    const std::string p = dot_choice(c, {"color", "depth"}, "a fragment program output");
    if (p == "color" && c.peek().is("[")) {
      if (!draw_buffers) {
        c.fail(
            "expected result.color without an index: result.color[n] needs OPTION "
            "ARB_draw_buffers");
      }
      return indexed("result.color", bracket_index(c, limits.draw_buffers, "a draw buffer"));
    }
    return "result." + p;
  }
  const std::string p = dot_choice(c, {"position", "color", "fogcoord", "pointsize", "texcoord"},
                                   "a vertex program output");
  if (p == "color") {
    const std::string face = optional_dot_choice(c, {"front", "back"});
    const std::string which = optional_dot_choice(c, {"primary", "secondary"});
    return "result.color." + (face.empty() ? "front" : face) + "." +
           (which.empty() ? "primary" : which);
  }
  if (p == "texcoord") {
    return indexed("result.texcoord",
                   optional_bracket_index(c, limits.texture_coords, "a texture coordinate", 0));
  }
  return "result." + p;
}

std::vector<ParamSlot> parse_param_binding(Cursor& c, ProgramKind kind, const Limits& limits,
                                           bool ranges) {
  if (c.peek().is("program")) {
    c.take();
    const std::string which = dot_choice(c, {"env", "local"}, "a program parameter");
    const int limit = which == "env" ? limits.env_params : limits.local_params;
    int first = 0, last = 0;
    index_range(c, limit, "a program." + which + " parameter number", ranges, first, last);
    std::vector<ParamSlot> out;
    for (int k = first; k <= last; ++k) out.push_back(binding_slot(indexed("program." + which, k)));
    return out;
  }
  c.expect("state", "a state.* or program.* binding");
  if (c.peek().is(".") && c.peek(1).is("matrix")) {
    c.take();
    c.take();
    return matrix_binding(c, limits, ranges);
  }
  return {binding_slot(state_binding(c, kind, limits))};
}

}  // namespace lt::arbfp::text
