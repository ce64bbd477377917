// PhaseClock: named phases timed with RAII scopes. Phases keep the order in which they were
// first seen (the paper's order, "I create partial order", "II sort exterior faces", ...).
// A scope costs two steady_clock reads and one short linear lookup.
#pragma once
#include <chrono>
#include <string>
#include <utility>
#include <vector>

namespace vob {

class PhaseClock {
 public:
  class Scope {
   public:
    Scope(PhaseClock& clock, const char* name)
        : clock_(clock), name_(name), start_(std::chrono::steady_clock::now()) {}
    ~Scope() {
      clock_.add(name_, std::chrono::duration<double>(std::chrono::steady_clock::now() - start_)
                            .count());
    }
    Scope(const Scope&) = delete;
    Scope& operator=(const Scope&) = delete;

   private:
    PhaseClock& clock_;
    const char* name_;
    std::chrono::steady_clock::time_point start_;
  };

  Scope phase(const char* name) { return Scope(*this, name); }
  void add(const std::string& name, double seconds) {
    for (auto& p : phases_)
      if (p.first == name) {
        p.second += seconds;
        return;
      }
    phases_.emplace_back(name, seconds);
  }
  const std::vector<std::pair<std::string, double>>& phases() const { return phases_; }
  double total() const {
    double t = 0;
    for (const auto& p : phases_) t += p.second;
    return t;
  }
  void clear() { phases_.clear(); }

 private:
  std::vector<std::pair<std::string, double>> phases_;
};

}  // namespace vob
