// The ARB programs as instruction lists (paths/arbfp/arb_ir.h).
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <map>

#include "arb_cases.h"
#include "core/error.h"

namespace lt {
namespace {

// With LT_ARB_DUMP_DIR set, writes every generated program of every case (arb_cases.h), its
// notes and LUT, one file per scene and change: the generator's output must stay byte-identical
// across refactorings, and `diff -r` of two dumps says where it does not.
TEST(ArbDump, WritesEveryProgramWhenAsked) {
  const char* dir = std::getenv("LT_ARB_DUMP_DIR");
  if (!dir) GTEST_SKIP() << "set LT_ARB_DUMP_DIR to dump every generated program";
  fs::create_directories(dir);
  std::map<std::string, std::ofstream> files;
  size_t programs = 0;
  test::for_each_arb_case([&](const test::ArbCase& c) {
    const std::string key = c.label.substr(0, c.label.find(" k="));
    auto it = files.find(key);
    if (it == files.end()) {
      it = files.emplace(key, std::ofstream(fs::path(dir) / (test::test_param_name(key) + ".txt")))
               .first;
    }
    std::ofstream& out = it->second;
    out << "=== " << c.label << "\n";
    try {
      const arbfp::ArbPrograms p = arbfp::generate_arb(c.scene, c.material, c.variant, c.term);
      out << p.vertex << "\n--- fragment\n" << p.fragment << "\n--- notes\n";
      for (const std::string& n : p.notes) out << n << "\n";
      if (p.lut) out << "--- lut " << p.lut->size << " " << model::to_string(p.lut->format) << "\n";
      programs += 2;
    } catch (const InputError& e) {
      out << "--- throws: " << e.what() << "\n";
    }
  });
  std::cout << programs << " programs in " << files.size() << " files under " << dir << "\n";
}

}  // namespace
}  // namespace lt
