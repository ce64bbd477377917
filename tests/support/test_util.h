// Helpers shared by the tests: generated datasets, an orderer run checked by the oracle,
// temporary folders, expected input errors.
#pragma once
#include <stdlib.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>

#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "datasets/datasets.h"
#include "harness/bench/registry.h"
#include "harness/oracle/oracle.h"
#include "harness/scene/input_error.h"

namespace vob::test {

inline Scene make(const std::string& name, std::vector<std::pair<std::string, std::string>> kv = {}) {
  Params p;
  for (const auto& [k, v] : kv) p.set(k, v);
  return make_dataset(name, p);
}

// A generated dataset with the given parameters (the Params carry the name for messages).
inline Scene dataset(const std::string& name, const std::map<std::string, std::string>& set = {}) {
  Params p(name);
  for (const auto& [k, v] : set) p.set(k, v);
  return make_dataset(name, p);
}

// The small cell meshes of the HAVS tests: gap 4x4x9 with 2 gaps, a helix of 3000 cells,
// any other dataset with its defaults.
inline Scene small_mesh(const std::string& name) {
  if (name == "gap") return dataset(name, {{"nx", "4"}, {"ny", "4"}, {"nz", "9"}, {"gaps", "2"}});
  if (name == "helix") return dataset(name, {{"cells", "3000"}});
  return dataset(name);
}

// One orderer (a spec such as "xmpvo:predicates=exact") prepared on a fresh copy of the
// scene and one view ordered; `clock`, when given, receives the phases of the order.
inline Ordering run_orderer(const std::string& spec, const Scene& scene, const Camera& view,
                            PhaseClock* clock = nullptr) {
  auto o = make_orderer(spec);
  PhaseClock prep, own_clock;
  const Scene own = scene.fresh();
  o->prepare(own, prep);
  return o->order(view, clock ? *clock : own_clock);
}

// run_orderer(), the order checked by the oracle at `supersample`.
struct Outcome {
  Ordering ordering;
  OracleResult oracle;
};
inline Outcome run_checked(const std::string& spec, const Scene& scene, const Camera& view,
                           int supersample = 1) {
  Outcome r{run_orderer(spec, scene, view), {}};
  OracleOptions opt;
  opt.supersample = supersample;
  r.oracle = check_ordering(scene, view, r.ordering.order, opt);
  return r;
}

// A shell command's exit code (-1 when it did not exit) and standard output.
struct CommandOutput {
  int code;
  std::string out;
};
inline CommandOutput run_command(const std::string& cmd) {
  FILE* p = popen(cmd.c_str(), "r");
  std::string out;
  char buf[4096];
  size_t n;
  while ((n = fread(buf, 1, sizeof buf, p)) > 0) out.append(buf, n);
  const int status = pclose(p);
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, out};
}

// The program under test (`binary`, the tests' VOB_BINARY) run with `args`, its stdout and
// stderr together, as a user at a terminal sees them.
inline CommandOutput run_vobench(const std::string& binary, const std::string& args) {
  return run_command(binary + " " + args + " 2>&1");
}

// `name` in a folder of this test process, temp/PREFIX_PID (created; kept for inspection).
inline std::filesystem::path scratch_path(const std::string& prefix, const std::string& name) {
  const std::filesystem::path d = std::filesystem::temp_directory_path() / (prefix + "_" + std::to_string(getpid()));
  std::filesystem::create_directories(d);
  return d / name;
}

// A fresh folder under the system temp dir, removed at scope exit.
struct TempDir {
  std::string path;
  TempDir() {
    std::string pattern = (std::filesystem::temp_directory_path() / "vob-datasets-XXXXXX").string();
    std::vector<char> buf(pattern.begin(), pattern.end());
    buf.push_back('\0');
    path = mkdtemp(buf.data());
  }
  ~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(path, ec);
  }
  std::string file(const std::string& name) const { return path + "/" + name; }
};

// Runs f and returns the InputError message ("" and a test failure when none is thrown).
template <class F>
std::string input_error(F&& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no InputError thrown";
  return "";
}

inline bool contains(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

}  // namespace vob::test
