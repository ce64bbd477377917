// ResultsFile: records reach the file at once, several writers merge without duplicates,
// a torn last line is repaired, bad files are one-line errors, files get the umask's mode.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "harness/bench/results.h"
#include "harness/scene/input_error.h"
#include "tests/support/test_util.h"

using namespace vob;
namespace fs = std::filesystem;

namespace {
fs::path scratch(const std::string& name) {
  const fs::path d = fs::temp_directory_path() / ("vob_results_test_" + std::to_string(getpid()));
  fs::create_directories(d);
  const fs::path p = d / name;
  fs::remove_all(p);
  return p;
}

std::string text_of(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

void put(const fs::path& p, const std::string& text) { std::ofstream(p) << text; }

// Keys on disk with how often each occurs.
std::map<std::string, int> key_counts(const fs::path& p) {
  std::map<std::string, int> out;
  for (const auto& r : ResultsFile::read_all(p.string())) ++out[r.at("key").get<std::string>()];
  return out;
}

nlohmann::json record(const std::string& key) { return {{"key", key}, {"x", 1}}; }
}  // namespace

TEST(ResultsFile, EveryAppendIsOnDiskAtOnce) {
  const fs::path p = scratch("at_once.jsonl");
  ResultsFile f(p.string());
  EXPECT_TRUE(f.append(record("a")));
  EXPECT_EQ(ResultsFile::read_all(p.string()).size(), 1u);  // while f is still open
  EXPECT_TRUE(f.append(record("b")));
  EXPECT_EQ(ResultsFile::read_all(p.string()).size(), 2u);
  EXPECT_FALSE(f.append(record("a")));  // a key is written once
  EXPECT_EQ(ResultsFile::read_all(p.string()).size(), 2u);
  EXPECT_EQ(f.size(), 2u);
  EXPECT_THROW(f.append({{"x", 1}}), std::logic_error);
}

TEST(ResultsFile, ReopeningRemembersKeys) {
  const fs::path p = scratch("reopen.jsonl");
  {
    ResultsFile f(p.string());
    f.append(record("a"));
    f.append(record("b"));
  }
  ResultsFile g(p.string());
  EXPECT_TRUE(g.has("a"));
  EXPECT_TRUE(g.has("b"));
  EXPECT_FALSE(g.has("c"));
  EXPECT_EQ(g.size(), 2u);
}

TEST(ResultsFile, TwoWritersMergeAndSeeEachOthersKeys) {
  const fs::path p = scratch("merge.jsonl");
  ResultsFile a(p.string()), b(p.string());
  EXPECT_TRUE(a.append(record("1")));
  EXPECT_TRUE(b.append(record("2")));
  EXPECT_TRUE(a.has("2"));          // read from the file, not from a's memory
  EXPECT_FALSE(b.append(record("1")));  // a wrote it first
  EXPECT_TRUE(a.append(record("3")));
  EXPECT_EQ(key_counts(p), (std::map<std::string, int>{{"1", 1}, {"2", 1}, {"3", 1}}));
  EXPECT_EQ(b.size(), 2u);  // as of b's last look
  EXPECT_TRUE(b.has("3"));
  EXPECT_EQ(b.size(), 3u);
}

// Processes racing on the same keys: the file holds each key once, and the appends that
// reported success are exactly the records on disk.
TEST(ResultsFile, RacingProcessesNeitherLoseNorDuplicate) {
  const fs::path p = scratch("race.jsonl");
  constexpr int kProcesses = 4, kKeys = 60;
  std::vector<pid_t> pids;
  for (int c = 0; c < kProcesses; ++c) {
    const pid_t pid = fork();
    ASSERT_GE(pid, 0);
    if (pid == 0) {
      int written = 0;
      try {
        ResultsFile f(p.string());
        for (int k = 0; k < kKeys; ++k) {
          // Every process writes the shared keys and one key of its own per step.
          written += f.append(record("shared" + std::to_string(k)));
          written += f.append(record("own" + std::to_string(c) + "-" + std::to_string(k)));
        }
      } catch (...) {
        _exit(255);
      }
      _exit(written > 250 ? 254 : written);
    }
    pids.push_back(pid);
  }
  int reported = 0;
  for (pid_t pid : pids) {
    int status = 0;
    ASSERT_EQ(waitpid(pid, &status, 0), pid);
    ASSERT_TRUE(WIFEXITED(status));
    ASSERT_LT(WEXITSTATUS(status), 254);
    reported += WEXITSTATUS(status);
  }
  const auto counts = key_counts(p);
  EXPECT_EQ(counts.size(), size_t(kKeys + kProcesses * kKeys));
  for (const auto& [key, n] : counts) EXPECT_EQ(n, 1) << key;
  EXPECT_EQ(reported, int(ResultsFile::read_all(p.string()).size()));
}

TEST(ResultsFile, TornLastLineIsCutOffAndCompleteRecordsKept) {
  const fs::path p = scratch("torn.jsonl");
  put(p, "{\"key\":\"a\"}\n{\"key\":\"b\"}\n{\"key\":\"c\",\"x\":[1,2");
  ResultsFile f(p.string());
  EXPECT_EQ(f.size(), 2u);
  EXPECT_TRUE(f.has("b"));
  EXPECT_FALSE(f.has("c"));
  EXPECT_EQ(text_of(p), "{\"key\":\"a\"}\n{\"key\":\"b\"}\n");
  EXPECT_TRUE(f.append(record("c")));
  EXPECT_EQ(ResultsFile::read_all(p.string()).size(), 3u);
}

TEST(ResultsFile, WholeRecordWithoutNewlineIsKept) {
  const fs::path p = scratch("no_newline.jsonl");
  put(p, "{\"key\":\"a\"}\n{\"key\":\"b\"}");
  ResultsFile f(p.string());
  EXPECT_TRUE(f.has("b"));
  EXPECT_EQ(text_of(p), "{\"key\":\"a\"}\n{\"key\":\"b\"}\n");
  EXPECT_TRUE(f.append(record("c")));
  EXPECT_EQ(key_counts(p).size(), 3u);
}

TEST(ResultsFile, TornLineLeftWhileOpenIsRepairedOnTheNextLook) {
  const fs::path p = scratch("torn_later.jsonl");
  ResultsFile f(p.string());
  f.append(record("a"));
  std::ofstream(p, std::ios::app) << "{\"key\":\"dead";  // a writer killed mid-line
  EXPECT_TRUE(f.append(record("b")));
  EXPECT_EQ(text_of(p), record("a").dump() + "\n" + record("b").dump() + "\n");
}

TEST(ResultsFile, MalformedLineIsOneLineInputError) {
  const fs::path p = scratch("bad.jsonl");
  put(p, "{\"key\":\"a\"}\n{oops\n{\"key\":\"c\"}\n");
  const std::string what = test::input_error([&] { ResultsFile f(p.string()); });
  EXPECT_TRUE(test::contains(what, "bad.jsonl")) << what;
  EXPECT_TRUE(test::contains(what, "line 2")) << what;
  EXPECT_FALSE(test::contains(what, "\n")) << what;
  put(p, "{\"key\":\"a\"}\n[1,2]\n");
  EXPECT_THROW(ResultsFile{p.string()}, InputError);
  put(p, "{\"key\":7}\n");
  EXPECT_THROW(ResultsFile{p.string()}, InputError);
  EXPECT_EQ(text_of(p), "{\"key\":7}\n");  // nothing repaired
}

TEST(ResultsFile, UnwritablePlacesAreInputErrors) {
  const fs::path file = scratch("plain_file");
  put(file, "x");
  EXPECT_THROW(ResultsFile{(file / "results.jsonl").string()}, InputError);  // parent is a file
  const fs::path dir = scratch("a_folder");
  fs::create_directories(dir);
  EXPECT_THROW(ResultsFile{dir.string()}, InputError);  // not a regular file
}

TEST(ResultsFile, RemovedFileIsCreatedAgain) {
  const fs::path p = scratch("removed.jsonl");
  ResultsFile f(p.string());
  f.append(record("a"));
  fs::remove(p);  // e.g. `reproduce --force` in another process
  EXPECT_FALSE(f.has("a"));
  EXPECT_TRUE(f.append(record("a")));
  EXPECT_EQ(key_counts(p).size(), 1u);
}

// `--force` on one reproduction: its records go, context lines and others' records stay in
// order, and a writer that had the file open before goes on in the new file.
TEST(ResultsFile, RemoveRecordsKeepsTheOthersAndTheWritersGoOn) {
  const fs::path p = scratch("remove.jsonl");
  put(p, R"({"type":"context","key":"context|r1","run_id":"r1","context":{}})" "\n"
         R"({"key":"a/1","reproduction":"a"})" "\n"
         R"({"key":"b/1","reproduction":"b"})" "\n"
         R"({"key":"a/2","reproduction":"a"})" "\n");
  ResultsFile other(p.string());  // another run's writer, opened before
  ResultsFile f(p.string());
  const auto removed = f.remove_records([](const nlohmann::json& r) { return r.value("reproduction", "") == "a"; });
  ASSERT_EQ(removed.size(), 2u);
  EXPECT_EQ(removed[0].at("key"), "a/1");
  EXPECT_EQ(removed[1].at("key"), "a/2");
  EXPECT_EQ(text_of(p), R"({"type":"context","key":"context|r1","run_id":"r1","context":{}})" "\n"
                        R"({"key":"b/1","reproduction":"b"})" "\n");
  EXPECT_FALSE(f.has("a/1"));
  EXPECT_TRUE(f.has("b/1"));
  EXPECT_TRUE(f.append(record("a/1")));  // measured again
  EXPECT_FALSE(other.has("a/2"));        // the old writer reads the new file
  EXPECT_FALSE(other.append(record("a/1")));
  EXPECT_TRUE(other.append(record("c/1")));
  EXPECT_EQ(key_counts(p), (std::map<std::string, int>{{"a/1", 1}, {"b/1", 1}, {"c/1", 1}}));
  EXPECT_TRUE(f.remove_records([](const nlohmann::json&) { return false; }).empty());
}

TEST(ResultsFile, NewFileGetsTheUmasksMode) {
  for (const mode_t mask : {mode_t(022), mode_t(027)}) {
    const mode_t old = umask(mask);
    const fs::path p = scratch("mode.jsonl");
    { ResultsFile f(p.string()); }
    umask(old);
    struct stat st {};
    ASSERT_EQ(stat(p.c_str(), &st), 0);
    EXPECT_EQ(st.st_mode & 0777, 0666 & ~mask);
  }
}
