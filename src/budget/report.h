// The one budget report of `ltrender budget` (docs/budget.md, schema ltrender-budget-2): what a
// scene's generated programs or a hand-written program file use of a hardware profile, whatever
// the path that counts them (arbfp: ARB instructions; combiners: GL 1.3 texture-environment
// stages; gx: TEV stages). Each path fills it with its own counter; one text writer and one JSON
// writer print every kind of input alike, and an invalid file is a record of its own.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/error.h"

namespace lt::budget {

// What a row of the report counts in: one program (an ARB program, a .comb file), one pass (a
// GX pass program, a pass of the arbfp pass plan), or one material (the worst of its programs,
// its passes, the translucency term's cost).
enum class Scope { Program, Pass, Material };
const char* to_string(Scope scope);

// A second, independent counter's figure for the same resource (Mesa's GL_PROGRAM_NATIVE_* for
// a hand-written ARB program) and whether it is what the rule predicts from ours.
struct CrossCheck {
  int value = 0;
  bool agrees = true;
};

// One resource of one row: "ALU instructions" 24 of 64.
struct Resource {
  std::string key;           // the JSON name: "alu", "tev_stages", "texture_units", ...
  std::string label;         // "ALU instructions"
  int used = 0;              // what the row uses, checked against the limit
  std::optional<int> limit;  // the profile's; none where it sets no limit of this kind
  std::string rule;          // how `used` is counted (and how the cross-check relates), if said
  std::optional<CrossCheck> check;  // see CrossCheck; none where there is no second counter
  bool over() const { return limit && used > *limit; }
};

struct Item {
  Scope scope = Scope::Program;
  std::string name;      // "material marble: fragment program", "ltrender_marble_pass0"
  std::string material;  // the material it belongs to, empty when none is known
  std::string program;   // the program file(s) it is, for a combiners material
  std::string profile;   // the profile its limits come from, empty for rows without limits
  std::vector<Resource> resources;
  std::string note;  // one line said of the row as a whole (no limit, amortised cost, ...)

  const Resource* find(const std::string& key) const;
  // The resource's used figure; LT_CHECK that the row has it.
  int used(const std::string& key) const;
};

struct ProfileUse {
  std::string name;        // as given to --profile
  std::string applies_to;  // "fragment programs", "vertex programs", "" for every row
  std::string summary;     // the hardware it stands for and where the numbers come from
};

// A fact about the input that is not a count ("header": "!!ARBfp1.0"), or a figure that is not
// checked against a limit (Mesa's API instruction count).
struct Detail {
  std::string key, text;
  std::optional<int> number;  // printed instead of text when set
};

struct Report {
  std::string file;     // the scene or the program file, as given
  std::string input;    // "scene" or "program" (a program file)
  std::string path;     // the path whose counter counted it: arbfp, combiners, gx
  std::string variant;  // the path's variant, for a scene; empty for a program file
  std::vector<ProfileUse> profiles;
  // Who the CrossChecks are from: a short name for the rows ("Mesa") and what it is.
  std::string check_name, check_source;
  std::vector<Detail> details;
  std::vector<Item> items;
  std::vector<std::string> notes;  // lines said of the input as a whole

  bool fits() const;
  // The most any row uses of `key` (the worst material's stages, the frame's passes); 0 when no
  // row counts it.
  int most(const std::string& key) const;
  // "FILE: " + overrun_line of the first resource over its limit; empty when it fits. The
  // failure line of `budget` (exit 1).
  std::string first_overrun() const;
};

// "material marble: fragment program: ALU instructions: 70 > 64 (ps_2_0)": one resource over
// its limit.
std::string overrun_line(const Item& item, const Resource& resource);

// The text the command prints: every line that reports on the file starts with the file.
std::string to_text(const Report& report);
// The ltrender-budget-2 object (docs/budget.md), printed on one line per file with `indent` < 0,
// else pretty-printed.
std::string to_json(const Report& report, int indent = 2);
// The record `budget --json` prints for a file that is not valid input: schema, file, fits
// null, and the error (the file it names, which may be one the input reads, where, what).
std::string error_json(const std::string& file, const InputError& error, int indent = 2);

constexpr const char* kSchema = "ltrender-budget-2";

}  // namespace lt::budget
