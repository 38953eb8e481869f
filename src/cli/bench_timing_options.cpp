#include "cli/bench_timing_options.h"

#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "cli/commands.h"

namespace lt::cli {

namespace {

// "precise 0.5, quick 0.25": a setting in each mode, for the help text.
template <typename T>
std::string in_each_mode(T BenchOptions::*setting) {
  BenchOptions precise, quick;
  set_timing_mode(quick, TimingMode::Quick);
  std::ostringstream s;
  s << "precise " << precise.*setting << ", quick " << quick.*setting;
  return s.str();
}

// The last place `option` was given on the command line, -1 if it was not.
long last_given(const CLI::App& app, const CLI::Option* option) {
  const std::vector<CLI::Option*>& order = app.parse_order();
  for (std::size_t i = order.size(); i-- > 0;) {
    if (order[i] == option) return static_cast<long>(i);
  }
  return -1;
}

}  // namespace

std::function<void()> add_timing_options(CLI::App& sub, BenchOptions& o) {
  // What the options said, apart from the mode; applied over the mode's values after parsing.
  auto given = std::make_shared<BenchOptions>();
  CLI::Option* quick = sub.add_flag("--quick")->description(
      "Quick timing: one round and a short minimum time, for comparing variants by hand (the "
      "report says it was quick)");
  CLI::Option* precise = sub.add_flag("--precise")
                             ->description(
                                 "Precise timing, the default: rounds to a +-2% interval (the CI "
                                 "standard of metrics.md)");
  struct Setting {
    CLI::Option* option;
    std::function<void(BenchOptions&)> take;  // copies the given value into the options
  };
  const auto take = [given](auto BenchOptions::*setting) {
    return [given, setting](BenchOptions& to) { to.*setting = (*given).*setting; };
  };
  const std::vector<Setting> settings = {
      {sub.add_option("--rounds", given->rounds,
                      "Rounds each figure is timed in at 1280x720, each in a session of its own "
                      "(" +
                          in_each_mode(&BenchOptions::rounds) + ")")
           ->check(CLI::Range(1, 20)),
       take(&BenchOptions::rounds)},
      {sub.add_option("--min-time", given->min_time_s,
                      "Least measuring time per path at 1280x720, in seconds, interleaved with "
                      "flat (" +
                          in_each_mode(&BenchOptions::min_time_s) + ")")
           ->check(FiniteRange(0.0, 60.0)),
       take(&BenchOptions::min_time_s)},
      {sub.add_option("--target-interval", given->target_interval,
                      "Beyond --min-time, keep pairing while the ratio's 95% interval is wider "
                      "than +- this fraction of it (" +
                          in_each_mode(&BenchOptions::target_interval) + ")")
           ->check(FiniteRange(0.0, 1.0)),
       take(&BenchOptions::target_interval)},
      {sub.add_option("--max-time", given->max_time_s,
                      "Most measuring time per path at 1280x720 while the interval is wider than "
                      "the target, in seconds (" +
                          in_each_mode(&BenchOptions::max_time_s) + "; never below --min-time)")
           ->check(FiniteRange(0.0, 60.0)),
       take(&BenchOptions::max_time_s)},
  };
  for (const Setting& s : settings) s.option->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);
  return [&sub, &o, quick, precise, settings]() {
    const long quick_at = last_given(sub, quick), precise_at = last_given(sub, precise);
    set_timing_mode(o, quick_at > precise_at ? TimingMode::Quick : TimingMode::Precise);
    const long mode_at = std::max(quick_at, precise_at);
    o.timing_overrides.clear();
    for (const Setting& s : settings) {
      if (last_given(sub, s.option) <= mode_at) continue;
      s.take(o);
      o.timing_overrides.push_back(s.option->get_name());
    }
  };
}

}  // namespace lt::cli
