// A C++ sorter speaking vobench's sorter protocol (README "Judging your own sorter"), for
// the protocol tests: cells back to front by centroid eye distance (what the built-in
// `centroid` does), or, by its first argument, a broken sorter:
//   drop: leaves out the last cell; crash: aborts at view 1; hang: never answers;
//   nonsense: answers a line that is not JSON; repeat: lists cell 0 twice;
//   exit1_after: answers every view, then fails (stderr line, status 1) at the end of its
//   input; linger: answers every view, then never exits; slowclock: claims a sort phase of
//   1000 s (longer than any round trip).
#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <iostream>
#include <string>
#include <thread>

#include <nlohmann/json.hpp>

#include "datasets/datasets.h"

int main(int argc, char** argv) {
  const std::string mode = argc > 1 ? argv[1] : "ok";
  const char* path = std::getenv("VOBENCH_SCENE");
  const char* kind = std::getenv("VOBENCH_KIND");
  if (!path || !kind || std::string(kind) != "cells") {
    std::cerr << "external_sorter: needs VOBENCH_SCENE and VOBENCH_KIND=cells\n";
    return 1;
  }
  const vob::Scene scene = vob::load_input(path);
  const auto& c = scene.cell_centroids().points;
  std::vector<float> key(c.size());
  std::vector<int32_t> order(c.size());
  std::string line;
  for (int view = 0; std::getline(std::cin, line); ++view) {
    const nlohmann::json request = nlohmann::json::parse(line);
    const auto& e = request["camera"]["eye"];
    const vob::Vec3 eye{e[0].get<double>(), e[1].get<double>(), e[2].get<double>()};
    const auto t0 = std::chrono::steady_clock::now();
    for (size_t i = 0; i < c.size(); ++i) {
      key[i] = static_cast<float>(-vob::length(c[i] - eye));
      order[i] = static_cast<int32_t>(i);
    }
    std::stable_sort(order.begin(), order.end(), [&](int32_t a, int32_t b) { return key[a] < key[b]; });
    const double sort_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (mode == "crash" && view == 1) std::abort();
    if (mode == "hang") std::this_thread::sleep_for(std::chrono::hours(1));
    if (mode == "nonsense") {
      std::cout << "{\"order\": [1, 2, oops" << std::endl;
      continue;
    }
    std::vector<int32_t> answer = order;
    if (mode == "drop") answer.pop_back();
    if (mode == "repeat") answer[1] = answer[0];
    std::cout << nlohmann::json{{"order", answer}, {"phases", {{"sort", mode == "slowclock" ? 1000.0 : sort_seconds}}}}.dump()
              << std::endl;
  }
  if (mode == "exit1_after") {
    std::cerr << "external_sorter: failing at the end" << std::endl;
    return 1;
  }
  if (mode == "linger") std::this_thread::sleep_for(std::chrono::hours(1));
  return 0;
}
