#include "regress/junit.h"

#include <map>
#include <sstream>

#include "core/fixed.h"
#include "core/fs.h"
#include "core/markup.h"
#include "report/tool_versions.h"

namespace lt {

namespace {

// A case that never gave a verdict (its worker crashed or ran out of time) is a JUnit error, as
// a test that threw is: the reporters show it apart from a failed comparison.
bool is_error(CaseStatus s) {
  return s == CaseStatus::kCrashed || s == CaseStatus::kTimedOut;
}

struct Counts {
  size_t tests = 0, failures = 0, errors = 0, skipped = 0;
  double seconds = 0;
  void add(const CaseResult& r) {
    ++tests;
    failures += is_failure(r.status) && !is_error(r.status);
    errors += is_error(r.status);
    skipped += r.status == CaseStatus::kSkipped;
    seconds += r.seconds;
  }
  std::string attributes() const {
    return "tests=\"" + std::to_string(tests) + "\" failures=\"" + std::to_string(failures) +
           "\" errors=\"" + std::to_string(errors) + "\" skipped=\"" + std::to_string(skipped) +
           "\" time=\"" + lt::fixed(seconds, 3) + "\"";
  }
};

// The case's output: a warning's message (JUnit has no warn: the reporters show a passing case's
// output, so the warning goes there), and the images a reviewer looks at first.
std::string system_out(const CaseResult& r, const fs::path& report_dir) {
  std::string out = r.status == CaseStatus::kWarn ? "warn: " + r.message : "";
  if (!report_dir.empty()) {
    for (const std::string* image : {&r.image, &r.golden_image, &r.heatmap}) {
      if (image->empty()) continue;
      out += (out.empty() ? "" : "\n") +
             ("[[ATTACHMENT|" + attachment_path(report_dir, *image) + "]]");
    }
  }
  return out;
}

void write_testcase(std::ostringstream& x, const CaseResult& r, const std::string& label,
                    const fs::path& report_dir) {
  const RegressCase& c = r.regress_case;
  x << "    <testcase classname=\"regress." << markup_escape(label.empty() ? "" : label + ".")
    << markup_escape(c.scene) << "\" name=\"" << markup_escape(c.path->name + ":" + c.variant)
    << "\" time=\"" << fixed(r.seconds, 3) << "\"";
  if (!is_failure(r.status) && r.status != CaseStatus::kSkipped && r.status != CaseStatus::kWarn) {
    x << "/>\n";
    return;
  }
  x << ">\n";
  if (is_error(r.status)) {
    x << "      <error type=\"" << to_string(r.status) << "\" message=\""
      << markup_escape(r.message) << "\">" << markup_escape(r.details) << "</error>\n";
  } else if (r.status == CaseStatus::kSkipped) {
    x << "      <skipped message=\"" << markup_escape(r.message) << "\"/>\n";
  } else if (r.status != CaseStatus::kWarn) {
    x << "      <failure type=\""
      << (r.status == CaseStatus::kMissing ? "missing-golden" : "regress") << "\" message=\""
      << markup_escape(r.message) << "\">"
      << markup_escape("golden: " + r.golden.string() + "\n" + r.details) << "</failure>\n";
  }
  const std::string out = system_out(r, report_dir);
  if (!out.empty()) x << "      <system-out>" << markup_escape(out) << "</system-out>\n";
  x << "    </testcase>\n";
}

}  // namespace

std::string attachment_path(const fs::path& report_dir, const std::string& image) {
  fs::path p = (report_dir / image).lexically_normal();
  if (p.is_absolute()) {
    std::error_code ec;
    const fs::path here = fs::current_path(ec);
    const fs::path inside = ec ? fs::path() : p.lexically_relative(here);
    if (!inside.empty() && *inside.begin() != "..") p = inside;
  }
  return p.string();
}

std::string junit_xml(const RegressRun& run, const std::string& label, const fs::path& report_dir) {
  Counts all;
  std::map<std::string, Counts> per_scene;
  std::vector<std::string> scene_order;
  for (const CaseResult& r : run.results) {
    all.add(r);
    if (!per_scene.count(r.regress_case.scene)) scene_order.push_back(r.regress_case.scene);
    per_scene[r.regress_case.scene].add(r);
  }
  const std::string versions = markup_escape(tool_versions_line());
  std::ostringstream x;
  x << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
    << "<testsuites name=\"ltrender regress " << markup_escape(label.empty() ? "" : label + " ")
    << "(shard " << run.shard.to_string() << ")\" " << all.attributes() << ">\n";
  for (const std::string& scene : scene_order) {
    x << "  <testsuite name=\"" << markup_escape(label.empty() ? scene : label + "/" + scene)
      << "\" " << per_scene[scene].attributes() << ">\n";
    // In every suite: JUnit's schema has properties per testsuite, not per testsuites.
    x << "    <properties><property name=\"ltrender.versions\" value=\"" << versions
      << "\"/></properties>\n";
    for (const CaseResult& r : run.results) {
      if (r.regress_case.scene == scene) write_testcase(x, r, label, report_dir);
    }
    x << "  </testsuite>\n";
  }
  x << "</testsuites>\n";
  return x.str();
}

}  // namespace lt
