// ltrender: thin main. Parses the command line, dispatches to a subcommand, and maps failures
// to the exit codes of cli.md: 0 success, 1 a check failed, 2 bad input or usage (one line).
#include <cstddef>
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include "cli/commands.h"
#include "core/error.h"
#include "report/tool_versions.h"

namespace {

int usage_error(const std::string& what) {
  lt::print_input_error(what);
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "ltrender: translucency (Barre-Brisebois & Bouchard, GDC 2011) on low-end pipelines"};
  app.require_subcommand(1);
  app.set_help_all_flag("--help-all", "Help for every subcommand");
  // Measured only when asked for: it starts a GL context, the image module and Dolphin.
  app.set_version_flag(
      "--version", [] { return lt::tool_versions_line(); },
      "Print ltrender's version and those of Mesa, OpenImageIO, Embree and Dolphin, then exit");

  using Registration = lt::cli::Action (*)(CLI::App&);
  const std::vector<Registration> registrations = {
      lt::cli::add_render,  lt::cli::add_compare, lt::cli::add_info,    lt::cli::add_bench,
      lt::cli::add_bake,    lt::cli::add_budget,  lt::cli::add_meshgen, lt::cli::add_export,
      lt::cli::add_regress, lt::cli::add_advise,  lt::cli::add_sweep,
  };
  std::vector<lt::cli::Action> actions;
  for (auto reg : registrations) actions.push_back(reg(app));

  // CLI11 takes an unknown first word for a stray argument and reports "A subcommand is
  // required"; name the word and the subcommands instead.
  if (argc > 1 && argv[1][0] != '-') {
    std::string names;
    bool known = false;
    for (const CLI::App* sub : app.get_subcommands({})) {
      names += (names.empty() ? "" : ", ") + sub->get_name();
      known = known || sub->check_name(argv[1]);
    }
    if (!known)
      return usage_error(std::string("usage: unknown subcommand '") + argv[1] +
                         "' (subcommands: " + names + ")");
  }

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    // CLI11's own exit codes differ; cli.md says usage errors are exit 2 with one line.
    return usage_error(std::string("usage: ") + e.what());
  }

  const auto subs = app.get_subcommands();
  const std::vector<CLI::App*> all = app.get_subcommands({});
  for (size_t i = 0; i < all.size() && i < actions.size(); ++i) {
    if (all[i] != subs.front()) continue;
    try {
      return actions[i]();
    } catch (const lt::InputError& e) {
      return usage_error(e.what());
    } catch (const lt::CheckFailed& e) {
      std::fprintf(stderr, "ltrender: check failed: %s\n", lt::one_line(e.what()).c_str());
      return 1;
    } catch (const std::exception& e) {
      // Anything else is still reported as one line with a non-zero code, never a crash.
      return usage_error(e.what());
    }
  }
  return usage_error("usage: no subcommand");
}
