// The results check that `vobench report` runs before the Python report sees a file.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "harness/cli/report_input.h"
#include "harness/scene/input_error.h"

using namespace vob;

namespace {
nlohmann::json record() {
  return nlohmann::json::parse(R"({"key": "k", "algorithm": "mpvo", "dataset": "gap", "w": 8, "h": 8,
      "n": 6, "phases": {"order": {"median": 0.1}}, "total": {"median": 0.1},
      "prepare": {"seconds": 0.0}, "cycles": {"count": 0}, "bytes": {"orderer": 1, "derived": 2},
      "oracle": {"covered_pixels": 4, "violating_pixels": 0, "max_k": 0}})");
}
}  // namespace

TEST(ReportInput, AcceptsARecordAndNamesTheFirstProblem) {
  EXPECT_EQ(report_record_problem(record()), "");
  auto r = record();
  r.erase("algorithm");
  EXPECT_EQ(report_record_problem(r), "field 'algorithm' is missing");
  r = record();
  r["total"]["median"] = "fast";
  EXPECT_EQ(report_record_problem(r), "field 'total.median' must be a number");
  r = record();
  r["total"] = 3;
  EXPECT_EQ(report_record_problem(r), "field 'total' must be an object");
  r = record();
  r["w"] = 1.5;
  EXPECT_EQ(report_record_problem(r), "field 'w' must be an integer");
  r = record();
  r["phases"]["order"] = 3;
  EXPECT_EQ(report_record_problem(r), "field 'phases.order' must be an object with a number 'median'");
  r = record();
  r["images"] = {{"order", "a.png"}};
  EXPECT_EQ(report_record_problem(r), "field 'images.exact' must be a string");
  EXPECT_EQ(report_record_problem(nlohmann::json::array()), "is not a JSON object (a results record)");
}

TEST(ReportInput, FileErrorsNameTheFileAndLine) {
  const auto path = std::filesystem::temp_directory_path() /
                    ("vob_report_input_" + std::to_string(getpid()) + ".jsonl");
  std::ofstream(path) << record().dump() << "\n\n" << "[1]\n";
  try {
    check_report_inputs({path.string()});
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), path.string() + ": line 3: is not a JSON object (a results record)");
  }
  std::ofstream(path) << std::string(100000, '[') << "\n";
  EXPECT_THROW(check_report_inputs({path.string()}), InputError);
  std::ofstream(path) << "\n \n";
  try {
    check_report_inputs({path.string()});
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("holds no records"), std::string::npos) << e.what();
  }
  std::ofstream(path) << record().dump() << "\n";
  EXPECT_NO_THROW(check_report_inputs({path.string()}));
  std::filesystem::remove(path);
}

TEST(ReportInput, ContextLinesAreAcceptedButAreNoRecords) {
  const auto path = std::filesystem::temp_directory_path() /
                    ("vob_report_ctx_" + std::to_string(getpid()) + ".jsonl");
  const std::string ctx =
      R"({"key": "context|r1", "type": "context", "run_id": "r1", "schema_version": 2, "context": {"cpu": "x"}})";
  std::ofstream(path) << ctx << "\n" << record().dump() << "\n";
  EXPECT_NO_THROW(check_report_inputs({path.string()}));
  std::ofstream(path) << ctx << "\n";
  EXPECT_THROW(check_report_inputs({path.string()}), InputError);  // holds no records
  std::ofstream(path) << R"({"key": "context|r1", "type": "context"})" << "\n" << record().dump() << "\n";
  try {
    check_report_inputs({path.string()});
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("line 1: context line"), std::string::npos) << e.what();
  }
  std::filesystem::remove(path);
}

// A run stopped before its first record leaves plan lines alone: a results folder's pages say
// every planned job is missing (plans_suffice); results files without a record stay refused.
TEST(ReportInput, PlanLinesSufficeOnlyWhenAsked) {
  const auto path = std::filesystem::temp_directory_path() /
                    ("vob_report_plan_" + std::to_string(getpid()) + ".jsonl");
  std::ofstream(path) << R"({"key": "plan|r1|a/b", "type": "plan", "run_id": "r1", "suite": "a/b", "jobs": []})"
                      << "\n";
  EXPECT_NO_THROW(check_report_inputs({path.string()}, /*plans_suffice=*/true));
  EXPECT_THROW(check_report_inputs({path.string()}), InputError);
  std::ofstream(path) << R"({"key": "context|r1", "type": "context", "run_id": "r1", "context": {}})" << "\n";
  EXPECT_THROW(check_report_inputs({path.string()}, /*plans_suffice=*/true), InputError);  // no plan either
  std::filesystem::remove(path);
}

// A run killed mid-write leaves a last line without its newline: the report of its
// finished records must still be possible (run, merge and the table scripts skip it too);
// the same text with its newline, or anywhere else, stays bad input.
TEST(ReportInput, ATornLastLineIsLeftOutNotRefused) {
  const auto path = std::filesystem::temp_directory_path() /
                    ("vob_report_torn_" + std::to_string(getpid()) + ".jsonl");
  const std::string torn = record().dump().substr(0, 40);
  std::ofstream(path) << record().dump() << "\n" << torn;
  EXPECT_NO_THROW(check_report_inputs({path.string()}));
  std::ofstream(path) << record().dump() << "\n" << torn << "\n";
  EXPECT_THROW(check_report_inputs({path.string()}), InputError);
  std::ofstream(path) << torn << "\n" << record().dump() << "\n";
  EXPECT_THROW(check_report_inputs({path.string()}), InputError);
  std::ofstream(path) << "{";  // alone in its file: not a killed run's tail, a bad file
  EXPECT_THROW(check_report_inputs({path.string()}), InputError);
  std::filesystem::remove(path);
}
