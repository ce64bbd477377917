// Decoding one answer line of the sorter protocol (external_orderer.h):
// {"order": [ids], "phases": {"name": seconds}} with "phases" optional and other keys
// ignored. Streamed through nlohmann's SAX parser straight into the id vector: a DOM of a
// million numbers would cost more than many sorts.
#pragma once
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace vob {

struct SorterAnswer {
  std::vector<int32_t> order;
  std::vector<std::pair<std::string, double>> phases;
};

// Returns the reason the line is not an answer ("answered malformed JSON: '...'",
// "order[3] is \"x\", not an id", ...), empty when `out` holds it.
std::string decode_sorter_answer(const std::string& line, SorterAnswer& out);

}  // namespace vob
