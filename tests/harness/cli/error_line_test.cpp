// error_line: whatever a message quotes from a bad file, the printed line is one readable line.
#include <gtest/gtest.h>

#include "harness/cli/error_line.h"

using namespace vob;

TEST(ErrorLine, QuotesControlBytesAndBytesThatAreNotUtf8) {
  EXPECT_EQ(error_line("a.vtu: line 3: bad"), "a.vtu: line 3: bad");
  EXPECT_EQ(error_line("x\ny\r\x1b[31m\x7f"), "x\\x0ay\\x0d\\x1b[31m\\x7f");
  EXPECT_EQ(error_line(std::string("nul\0!", 5)), "nul\\x00!");
  EXPECT_EQ(error_line("caf\xc3\xa9"), "caf\xc3\xa9");        // well-formed UTF-8 stays
  EXPECT_EQ(error_line("\xff\xfe"), "\\xff\\xfe");             // never valid
  EXPECT_EQ(error_line("\xc3("), "\\xc3(");                    // lead byte without continuation
  EXPECT_EQ(error_line("\xe2\x82"), "\\xe2\\x82");             // truncated sequence
}

TEST(ErrorLine, CutsAVeryLongMessageAtACharacterBoundary) {
  const std::string line = error_line(std::string(5000, 'a'));
  EXPECT_EQ(line.size(), kMaxErrorLine + 6);
  EXPECT_EQ(line.substr(line.size() - 6), " [...]");
  std::string accents;
  for (int i = 0; i < 2000; ++i) accents += "\xc3\xa9";
  const std::string cut = error_line(accents);
  EXPECT_EQ(cut.substr(cut.size() - 6), " [...]");
  EXPECT_EQ((cut.size() - 6) % 2, 0u);  // no half character
  EXPECT_EQ(error_line(std::string(3000, '\x01')).find('\x01'), std::string::npos);
}
