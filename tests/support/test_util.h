// Helpers shared by the dataset tests.
#pragma once
#include <stdlib.h>

#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "datasets/datasets.h"
#include "harness/scene/input_error.h"

namespace vob::test {

inline Scene make(const std::string& name, std::vector<std::pair<std::string, std::string>> kv = {}) {
  Params p;
  for (const auto& [k, v] : kv) p.set(k, v);
  return make_dataset(name, p);
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
