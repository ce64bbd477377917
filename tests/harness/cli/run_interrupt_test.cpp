// `vobench run` never loses a finished record: runs interrupted by SIGINT, SIGTERM and
// SIGKILL at several moments, and two runs writing one file at once. Every record a run
// reported finished (its progress line) is compared with the records on disk.
#include <gtest/gtest.h>
#include <poll.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

extern char** environ;
namespace fs = std::filesystem;

namespace {
fs::path scratch(const std::string& name) {
  const fs::path d = fs::temp_directory_path() / ("vobench_interrupt_" + std::to_string(getpid()));
  fs::create_directories(d);
  return d / name;
}

// A vobench process whose stdout and stderr come back through one pipe, line by line.
class Vobench {
 public:
  explicit Vobench(const std::vector<std::string>& args) {
    int fds[2];
    if (pipe(fds) != 0) throw std::runtime_error("pipe");
    posix_spawn_file_actions_t fa;
    posix_spawn_file_actions_init(&fa);
    posix_spawn_file_actions_adddup2(&fa, fds[1], 1);
    posix_spawn_file_actions_adddup2(&fa, fds[1], 2);
    posix_spawn_file_actions_addclose(&fa, fds[0]);
    posix_spawn_file_actions_addclose(&fa, fds[1]);
    std::vector<std::string> all{VOB_BINARY};
    all.insert(all.end(), args.begin(), args.end());
    std::vector<char*> argv;
    for (auto& a : all) argv.push_back(a.data());
    argv.push_back(nullptr);
    const int err = posix_spawn(&pid_, VOB_BINARY, &fa, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&fa);
    close(fds[1]);
    fd_ = fds[0];
    if (err != 0) throw std::runtime_error("cannot start " VOB_BINARY);
  }
  ~Vobench() {
    if (pid_ > 0) {
      kill(pid_, SIGKILL);
      waitpid(pid_, nullptr, 0);
    }
    close(fd_);
  }
  // The next line, or false at the end of output. A silence of 120 s is a hang: fail.
  bool next_line(std::string& line) {
    for (;;) {
      const size_t nl = buffer_.find('\n');
      if (nl != std::string::npos) {
        line = buffer_.substr(0, nl);
        buffer_.erase(0, nl + 1);
        all_ += line + "\n";
        return true;
      }
      pollfd p{fd_, POLLIN, 0};
      if (poll(&p, 1, 120000) <= 0) throw std::runtime_error("vobench printed nothing for 120 s");
      char buf[4096];
      const ssize_t n = read(fd_, buf, sizeof buf);
      if (n <= 0) {
        if (!buffer_.empty()) {
          line = buffer_;
          all_ += line;
          buffer_.clear();
          return true;
        }
        return false;
      }
      buffer_.append(buf, size_t(n));
    }
  }
  void signal(int sig) { kill(pid_, sig); }
  // Reads the rest of the output, then the exit: the code, or 128 + signal if killed.
  int finish() {
    std::string line;
    while (next_line(line)) {
    }
    int status = 0;
    waitpid(pid_, &status, 0);
    pid_ = -1;
    return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  }
  const std::string& output() const { return all_; }

 private:
  pid_t pid_ = -1;
  int fd_ = -1;
  std::string buffer_, all_;
};

// A progress line of a finished record:
// "[k/N] MM:SS elapsed, ~MM:SS left: ALG on DATASET view I WxH tT: T ms/frame, ...".
bool finished_record(const std::string& line, std::string& label) {
  if (line.find(" ms/frame") == std::string::npos) return false;
  size_t start = line.find(" left: ");
  start = start == std::string::npos ? line.find(" unknown: ") + 10 : start + 7;
  label = line.substr(start, line.rfind(": ") - start);
  return true;
}

// The same label from a record on disk.
std::string label_of(const nlohmann::json& r) {
  return r["algorithm"].get<std::string>() + " on " + r["dataset"].get<std::string>() + " view " +
         std::to_string(r["view_index"].get<int>()) + " " + std::to_string(r["w"].get<int>()) + "x" +
         std::to_string(r["h"].get<int>()) + " t" + std::to_string(r["threads"].get<int>());
}

// Label -> how many lines of the file hold it. Every line must be a whole JSON record,
// except that where `torn` is given, a last line without its newline is counted there and
// left out: SIGKILL can stop a write() between two pages of a record (ext4 looks for a
// fatal signal before each page it copies), which tears the record in progress; the next
// run removes it.
std::map<std::string, int> on_disk(const fs::path& results, int* torn = nullptr) {
  std::map<std::string, int> out;
  std::ifstream in(results);
  std::string line;
  while (std::getline(in, line)) {
    if (torn && in.eof()) {  // getline met the end before a newline
      ++*torn;
      break;
    }
    const auto r = nlohmann::json::parse(line);
    if (!r.contains("type")) ++out[label_of(r)];  // not a run's context or plan line
  }
  return out;
}

int total(const std::map<std::string, int>& m) {
  int n = 0;
  for (const auto& [k, c] : m) n += c;
  return n;
}

// 3 orderers x 8 views: 24 records, each slow enough (repeats, oracle, image error) that a
// signal sent after one record line arrives while a later record is being computed.
constexpr int kRecords = 24;
fs::path write_suite(const std::string& name) {
  const fs::path p = scratch(name + ".json");
  std::ofstream(p) << R"({"name": ")" << name << R"(",
    "datasets": [{"name": "gap", "set": {"nx": 4, "ny": 4, "nz": 6}}],
    "algorithms": ["mpvo", "mpvonc", "centroid"], "views": 8, "sizes": ["96x96"],
    "repeats": 20, "warmup": 1, "oracle": true, "supersample": 2, "image_error": true})";
  return p;
}

struct Stopped {
  int code;
  std::set<std::string> reported;  // records the run said it finished
};

// Runs the suite into results and sends `sig` once `after` record lines were read (0: on
// the first line of output, before any record); sig 0 lets it finish.
Stopped run_and_signal(const fs::path& suite, const fs::path& results, int after, int sig) {
  Vobench v({"run", suite.string(), "-o", results.string()});
  Stopped s{0, {}};
  std::string line, label;
  int seen = 0;
  bool sent = sig == 0;
  while (v.next_line(line)) {
    if (finished_record(line, label)) {
      EXPECT_TRUE(s.reported.insert(label).second) << "reported twice: " << label;
      ++seen;
    }
    if (!sent && seen >= after) {
      v.signal(sig);
      sent = true;
    }
  }
  s.code = v.finish();
  if (sig == SIGINT || sig == SIGTERM) {
    EXPECT_NE(v.output().find("run the same command again to resume"), std::string::npos) << v.output();
  }
  return s;
}
}  // namespace

TEST(RunInterrupt, SigintAndSigtermKeepEveryFinishedRecordAndResume) {
  const fs::path suite = write_suite("interrupt");
  const fs::path results = scratch("interrupt.jsonl");
  fs::remove(results);
  std::set<std::string> reported;
  const std::vector<std::pair<int, int>> moments = {{0, SIGINT}, {1, SIGINT}, {3, SIGTERM}, {5, SIGINT}};
  for (const auto& [after, sig] : moments) {
    const Stopped s = run_and_signal(suite, results, after, sig);
    EXPECT_EQ(s.code, 128 + sig) << "after " << after;
    for (const auto& l : s.reported) EXPECT_TRUE(reported.insert(l).second) << "computed twice: " << l;
    const auto disk = on_disk(results);
    EXPECT_EQ(total(disk), int(disk.size())) << "a record is on disk twice";
    std::set<std::string> keys;
    for (const auto& [k, n] : disk) keys.insert(k);
    EXPECT_EQ(keys, reported) << "after a signal after " << after << " records";
  }
  EXPECT_LT(int(reported.size()), kRecords) << "the signals came too late to interrupt anything";
  const Stopped last = run_and_signal(suite, results, 0, 0);
  EXPECT_EQ(last.code, 0);
  for (const auto& l : last.reported) EXPECT_TRUE(reported.insert(l).second) << "computed twice: " << l;
  const auto disk = on_disk(results);
  EXPECT_EQ(int(disk.size()), kRecords);
  EXPECT_EQ(total(disk), kRecords);
  EXPECT_EQ(int(reported.size()), kRecords);
}

TEST(RunInterrupt, SigkillLosesAtMostTheRecordInProgress) {
  const fs::path suite = write_suite("kill");
  const fs::path results = scratch("kill.jsonl");
  fs::remove(results);
  std::set<std::string> reported;
  for (const int after : {0, 1, 4, 2}) {
    const Stopped s = run_and_signal(suite, results, after, SIGKILL);
    EXPECT_EQ(s.code, 128 + SIGKILL);
    reported.insert(s.reported.begin(), s.reported.end());
    int torn = 0;
    const auto disk = on_disk(results, &torn);
    EXPECT_EQ(total(disk), int(disk.size())) << "a record is on disk twice";
    int unreported = 0;
    for (const auto& [k, n] : disk) unreported += reported.count(k) == 0;
    for (const auto& l : reported) EXPECT_EQ(disk.count(l), 1u) << "reported but lost: " << l;
    // The record in progress when the kill came: on disk whole but not yet reported (killed
    // between its write and its line), or torn (killed in its write), or not there.
    EXPECT_LE(unreported + torn, 1);
    for (const auto& [k, n] : disk) reported.insert(k);
  }
  // A line torn by a kill in the middle of a write: the next run notes it and removes it.
  std::ofstream(results, std::ios::app) << R"({"key": "interrupt|mpvo|gap)";
  Vobench v({"run", suite.string(), "-o", results.string()});
  EXPECT_EQ(v.finish(), 0) << v.output();
  EXPECT_NE(v.output().find("incomplete last line"), std::string::npos) << v.output();
  const auto disk = on_disk(results);
  EXPECT_EQ(int(disk.size()), kRecords);
  EXPECT_EQ(total(disk), kRecords);
}

TEST(RunInterrupt, TwoRunsIntoOneFileKeepBothAndWriteEachKeyOnce) {
  const fs::path same = write_suite("same");
  const fs::path other = write_suite("other");
  const fs::path results = scratch("together.jsonl");
  fs::remove(results);
  // The same suite twice (they race for every key) and a third run of another suite.
  std::vector<std::unique_ptr<Vobench>> runs;
  for (const fs::path& s : {same, same, other})
    runs.push_back(std::make_unique<Vobench>(std::vector<std::string>{"run", s.string(), "-o", results.string()}));
  std::map<std::string, int> reported;  // "suite: label" -> runs that reported it
  const std::vector<std::string> names = {"same", "same", "other"};
  for (size_t i = 0; i < runs.size(); ++i) {
    std::string line, label;
    while (runs[i]->next_line(line))
      if (finished_record(line, label)) ++reported[names[i] + ": " + label];
    EXPECT_EQ(runs[i]->finish(), 0) << runs[i]->output();
  }
  std::map<std::string, int> disk;
  std::ifstream in(results);
  for (std::string line; std::getline(in, line);) {
    const auto r = nlohmann::json::parse(line);
    if (!r.contains("type")) ++disk[r["suite"].get<std::string>() + ": " + label_of(r)];
  }
  EXPECT_EQ(disk, reported);
  EXPECT_EQ(int(disk.size()), 2 * kRecords);
  for (const auto& [k, n] : disk) EXPECT_EQ(n, 1) << k;
}

TEST(RunInterrupt, UnwritableResultsFolderIsReportedBeforeAnyWork) {
  const fs::path suite = write_suite("nowhere");
  const fs::path plain = scratch("plain-file");
  std::ofstream(plain) << "x";
  Vobench v({"run", suite.string(), "-o", (plain / "results.jsonl").string()});
  EXPECT_EQ(v.finish(), 2) << v.output();
  EXPECT_NE(v.output().find("plain-file"), std::string::npos) << v.output();
  EXPECT_EQ(v.output().find("dataset 1/"), std::string::npos) << "work started: " << v.output();
  EXPECT_EQ(std::count(v.output().begin(), v.output().end(), '\n'), 1) << v.output();
}

// `reproduce` plans the run (what is done, at which scale) before its writer opens the file:
// a line torn by a kill must not stop it from resuming. And records of another build are
// kept but named, with how to measure them again.
TEST(RunInterrupt, ReproduceResumesAfterATornLineAndNamesOtherBuilds) {
  const fs::path dir = scratch("repro");
  fs::remove_all(dir);
  {
    Vobench v({"reproduce", "quick", "--tiny", "-o", dir.string()});
    ASSERT_EQ(v.finish(), 0) << v.output();
  }
  const fs::path results = dir / "results.jsonl";
  // As if an older build had written them: its runs' context lines name another revision.
  std::vector<std::string> lines;
  {
    std::ifstream in(results);
    for (std::string l; std::getline(in, l);) {
      nlohmann::json j = nlohmann::json::parse(l);
      if (j.value("type", "") == "context") j["context"]["git_sha"] = "0ld0ld0";
      lines.push_back(j.dump());
    }
  }
  {
    std::ofstream out(results, std::ios::trunc);
    for (const auto& l : lines) out << l << "\n";
    out << R"({"key": "quick/quick|mpvo|gap)";  // torn by a kill
  }
  Vobench v({"reproduce", "quick", "--tiny", "-o", dir.string()});
  EXPECT_EQ(v.finish(), 0) << v.output();
  EXPECT_EQ(v.output().find("not valid JSON"), std::string::npos) << v.output();
  EXPECT_NE(v.output().find("incomplete last line"), std::string::npos) << v.output();
  EXPECT_NE(v.output().find("measured by other builds"), std::string::npos) << v.output();
  EXPECT_NE(v.output().find(" by 0ld0ld0), not by this one"), std::string::npos) << v.output();
  EXPECT_NE(v.output().find("--force measures them again"), std::string::npos) << v.output();
  // Nothing new was measured: every job was done.
  EXPECT_NE(v.output().find(" 0 records written"), std::string::npos) << v.output();
}

// `reproduce all` writes every paper into one folder: `--force` on one reproduction drops
// its own records and no other's (it once removed the whole results file).
TEST(RunInterrupt, ForceDropsOnlyItsOwnReproductionsRecords) {
  const fs::path dir = scratch("force-shared");
  fs::remove_all(dir);
  for (const char* name : {"quick", "threads"}) {
    Vobench v({"reproduce", name, "--tiny", "-o", dir.string()});
    ASSERT_EQ(v.finish(), 0) << v.output();
  }
  const auto count = [&](const std::string& name) {
    size_t n = 0;
    std::ifstream in(dir / "results.jsonl");
    for (std::string l; std::getline(in, l);) {  // records only, not the suites' plan lines
      const auto j = nlohmann::json::parse(l);
      n += !j.contains("type") && j.value("reproduction", "") == name;
    }
    return n;
  };
  const size_t quick = count("quick"), threads = count("threads");
  ASSERT_GT(quick, 0u);
  ASSERT_GT(threads, 0u);
  Vobench v({"reproduce", "quick", "--tiny", "--force", "-o", dir.string()});
  EXPECT_EQ(v.finish(), 0) << v.output();
  EXPECT_NE(v.output().find("--force: " + std::to_string(quick) + " records of quick removed"), std::string::npos)
      << v.output();
  EXPECT_EQ(count("threads"), threads);
  EXPECT_EQ(count("quick"), quick);  // measured again
}

