// vents.csv (src/io/vent_log.hpp): each vent's exchange since the last output, its net air flux, resumable; and the
// `simulate` command's file agrees with diagnostics.csv's totals and with a resumed run.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "cli/simulate.hpp"
#include "io/vent_log.hpp"
#include "support/air_column.hpp"
#include "support/scratch.hpp"

namespace fs = std::filesystem;
using namespace mistfall;
using test_support::csvFields;
using test_support::freshDir;

namespace {

std::vector<std::string> linesOf(const fs::path& file) {
  std::ifstream in(file);
  std::vector<std::string> out;
  for (std::string l; std::getline(in, l);) out.push_back(l);
  return out;
}

int simulateQuietly(const SimulateOptions& o) {
  std::ostringstream err;
  std::streambuf* old = std::cerr.rdbuf(err.rdbuf());
  const int code = runSimulate(o);
  std::cerr.rdbuf(old);
  return code;
}

}  // namespace

TEST(VentLog, WritesEachVentsExchangeAndItsAirFluxAndKeepsEarlierLinesOnResume) {
  const fs::path dir = freshDir("vent_log");
  const fs::path file = dir / "vents.csv";
  {
    VentLog log(file, {"cavity", "roof"}, 1e-4, std::nullopt);
    log.append(0.0, 0.0, {0, 0}, {0, 0});
    log.append(0.02, 0.02, {3, 10}, {7, 2}, {0, 5});  // cavity: 4 out; roof: 8 in, and 5 liquid out
    log.append(0.04, 0.02, {1, 0}, {0, 0});
  }
  auto all = linesOf(file);
  ASSERT_EQ(7u, all.size());
  EXPECT_EQ(VentLog::header(), all[0]);
  EXPECT_EQ((std::vector<std::string>{"0", "cavity", "0", "0", "0", "0"}), csvFields(all[1]));
  auto cavity = csvFields(all[3]), roof = csvFields(all[4]);
  EXPECT_EQ("cavity", cavity[1]);
  EXPECT_EQ("3", cavity[2]);
  EXPECT_EQ("7", cavity[3]);
  EXPECT_NEAR(4 * 1e-4 / 0.02, std::stod(cavity[4]), 1e-12);   // 0.02 m^2/s out
  EXPECT_NEAR(-8 * 1e-4 / 0.02, std::stod(roof[4]), 1e-12);    // 0.04 m^2/s in
  EXPECT_EQ("0", cavity[5]);
  EXPECT_EQ("5", roof[5]);
  {
    VentLog resumed(file, {"cavity", "roof"}, 1e-4, 0.02);  // the lines at t = 0.04 are dropped
    resumed.append(0.03, 0.01, {0, 0}, {1, 0});
  }
  all = linesOf(file);
  ASSERT_EQ(7u, all.size());
  EXPECT_EQ("0.029999999999999999", csvFields(all[5])[0]);
  EXPECT_EQ("1", csvFields(all[5])[3]);
}

// The command's vents.csv: one line a vent at every output time, the per-vent counts adding up to diagnostics.csv's
// totals, and a run resumed half-way writing the same file as the unbroken one.
TEST(VentLog, SimulateWritesEveryVentsCountsAndResumesThem) {
  const fs::path dir = freshDir("vent_log_simulate");
  std::string text = test_support::airColumnCase("", 0.2, test_support::ductVents());  // rising at 0.2 m/s
  const std::string end = "end_time = 1.0";
  text.replace(text.find(end), end.size(), "end_time = 0.1\ninterval = 0.02");
  const fs::path case_file = dir / "duct.toml";
  std::ofstream(case_file, std::ios::binary) << text;

  SimulateOptions whole;
  whole.case_file = case_file, whole.out_dir = dir / "whole", whole.threads = 1, whole.force_plain_progress = true;
  ASSERT_EQ(0, simulateQuietly(whole));
  const auto lines = linesOf(dir / "whole" / "vents.csv");
  ASSERT_EQ(1u + 6 * 2, lines.size());  // t = 0, 0.02, ..., 0.1: two vents each
  std::map<std::string, std::int64_t> in, out;
  for (std::size_t k = 1; k < lines.size(); ++k) {
    const auto f = csvFields(lines[k]);
    in[f[1]] += std::stoll(f[2]);
    out[f[1]] += std::stoll(f[3]);
  }
  EXPECT_GT(in["bottom"], 10);  // air enters at the bottom at about 200 particles a second
  EXPECT_GT(out["top"], 10);    // and leaves at the top
  const auto diagnostics = linesOf(dir / "whole" / "diagnostics.csv");
  const auto header = csvFields(diagnostics.front()), last = csvFields(diagnostics.back());
  std::int64_t vented_in = -1, vented_out = -1;
  for (std::size_t c = 0; c < header.size(); ++c) {
    if (header[c] == "vented_in") vented_in = std::stoll(last[c]);
    if (header[c] == "vented_out") vented_out = std::stoll(last[c]);
  }
  EXPECT_EQ(vented_in, in["bottom"] + in["top"]);
  EXPECT_EQ(vented_out, out["bottom"] + out["top"]);

  SimulateOptions first = whole;
  first.out_dir = dir / "resumed", first.until = 0.06;
  ASSERT_EQ(0, simulateQuietly(first));
  SimulateOptions second;
  second.out_dir = dir / "resumed", second.resume = true, second.threads = 1, second.force_plain_progress = true;
  ASSERT_EQ(0, simulateQuietly(second));
  EXPECT_EQ(lines, linesOf(dir / "resumed" / "vents.csv"));
}

// A run whose vents.csv was written before the liquid_out column: resumed, its kept lines get the column empty (not
// recorded), so every line has the header's six fields, and the new lines carry it.
TEST(VentLog, ResumingAnOlderFileLeavesTheNewColumnEmptyOnItsLines) {
  const fs::path dir = freshDir("vent_log_older");
  const fs::path file = dir / "vents.csv";
  std::ofstream(file, std::ios::binary) << "time,vent,gas_in,gas_out,air_out\n0,roof,0,0,0\n0.02,roof,3,1,-0.01\n";
  {
    VentLog resumed(file, {"roof"}, 1e-4, 0.02);
    resumed.append(0.04, 0.02, {0}, {2}, {1});
  }
  const auto all = linesOf(file);
  ASSERT_EQ(4u, all.size());
  EXPECT_EQ(VentLog::header(), all[0]);
  EXPECT_EQ("0.02,roof,3,1,-0.01,", all[2]);
  EXPECT_EQ((std::vector<std::string>{"0.040000000000000001", "roof", "0", "2", "0.01", "1"}), csvFields(all[3]));
}

TEST(VentLog, ACaseWithoutVentsWritesNone) {
  const fs::path dir = freshDir("vent_log_none");
  std::string text = test_support::airColumnCase("", 0.0, test_support::sealedEnds());
  const std::string end = "end_time = 1.0";
  text.replace(text.find(end), end.size(), "end_time = 0.01\ninterval = 0.01");
  std::ofstream(dir / "column.toml", std::ios::binary) << text;
  SimulateOptions o;
  o.case_file = dir / "column.toml", o.out_dir = dir / "run", o.threads = 1, o.force_plain_progress = true;
  ASSERT_EQ(0, simulateQuietly(o));
  EXPECT_TRUE(fs::exists(dir / "run" / "diagnostics.csv"));
  EXPECT_FALSE(fs::exists(dir / "run" / "vents.csv"));
}
