// The sorter protocol's answer line (sorter_answer.h): the fast path and the SAX decode
// agree on what is an answer, and every fault is named.
#include "harness/bench/sorter_answer.h"

#include <gtest/gtest.h>

namespace vob {
namespace {

std::string decode(const std::string& line, SorterAnswer& a) { return decode_sorter_answer(line, a); }

TEST(SorterAnswer, ReadsOrderAndPhasesInAnyShape) {
  for (const std::string line :
       {"{\"order\":[2,0,1]}", " { \"order\" : [ 2 , 0 ,1 ] , \"phases\": {\"sort\": 0.5, \"keys\": 1} } ",
        "{\"phases\": {\"sort\": 0.5, \"keys\": 1}, \"order\": [2, 0, 1]}",
        "{\"order\":[2,0,1],\"note\":{\"a\":[1,{\"b\":null}]},\"phases\":{\"sort\":5e-1,\"keys\":1}}"}) {
    SorterAnswer a;
    ASSERT_EQ(decode(line, a), "") << line;
    EXPECT_EQ(a.order, (std::vector<int32_t>{2, 0, 1})) << line;
    if (line.find("phases") != std::string::npos) {
      ASSERT_EQ(a.phases.size(), 2u) << line;
      EXPECT_EQ(a.phases[0].first, "sort");
      EXPECT_EQ(a.phases[0].second, 0.5);
      EXPECT_EQ(a.phases[1].second, 1.0);
    }
  }
  SorterAnswer a;
  EXPECT_EQ(decode("{\"order\": []}", a), "");
  EXPECT_TRUE(a.order.empty());
}

TEST(SorterAnswer, NamesEveryFault) {
  const std::pair<std::string, std::string> cases[] = {
      {"", "malformed JSON"},
      {"hello", "malformed JSON"},
      {"{\"order\": [1, 2", "malformed JSON"},
      {"{\"order\": [1, 2],}", "malformed JSON"},
      {"{\"order\": [01, 2]}", "malformed JSON"},
      {"{\"order\": [1, 2]} x", "malformed JSON"},
      {"[1, 2]", "no \"order\" array"},
      {"{\"ordr\": [1]}", "no \"order\" array"},
      {"{\"order\": 5}", "\"order\" is 5"},
      {"{\"order\": {\"a\": 1}}", "\"order\" is not an array"},
      {"{\"order\": [1, 2.5]}", "order[1] is 2.5, not an id"},
      {"{\"order\": [1, \"2\"]}", "order[1] is \"2\", not an id"},
      {"{\"order\": [1, [2]]}", "order[1] is an array"},
      {"{\"order\": [1, 99999999999]}", "order[1] is 99999999999"},
      {"{\"order\": [1], \"phases\": [1]}", "\"phases\" is not an object"},
      {"{\"order\": [1], \"phases\": {\"sort\": -1}}", "phase 'sort' is -1, not seconds"},
      {"{\"order\": [1], \"phases\": {\"sort\": \"fast\"}}", "phase 'sort' is \"fast\""},
      // Repeated members: the order-file reader kept the last "order", this decoder joined them.
      {"{\"order\": [0], \"order\": [1]}", "answered \"order\" twice"},
      {"{\"order\": [0], \"phases\": {}, \"order\": []}", "answered \"order\" twice"},
      {"{\"order\": [0], \"phases\": {}, \"phases\": {}}", "answered \"phases\" twice"},
      {"{\"order\": [0], \"phases\": {\"sort\": 1, \"sort\": 2}}", "phase 'sort' given twice"},
  };
  for (const auto& [line, want] : cases) {
    SorterAnswer a;
    const std::string why = decode(line, a);
    EXPECT_NE(why.find(want), std::string::npos) << "line " << line << " gave '" << why << "'";
  }
}

}  // namespace
}  // namespace vob
