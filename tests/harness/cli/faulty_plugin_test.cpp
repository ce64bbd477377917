// A plugin that calls exit(0) inside order() once ended `check` with status 0 and no
// verdict (a CI gate passed); one that threw gave a message that did not say whose it was.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <string>

#include "tests/support/test_util.h"

namespace {
vob::test::CommandOutput check(const std::string& orderer, const std::string& junit) {
  return vob::test::run_command(std::string(VOB_BINARY) + " --plugin " + VOB_FAULTY_PLUGIN +
                                " check -d gap --set nx=3 --set ny=3 --set nz=3 --views 2 --size 32x32 -a " + orderer +
                                " --junit " + junit + " 2>&1");
}
}  // namespace

TEST(FaultyPlugin, ExitInsideOrderIsAnInternalErrorNotAPass) {
  const std::string junit = (std::filesystem::temp_directory_path() / ("vob_faulty_" + std::to_string(getpid()) + ".xml")).string();
  const auto r = check("exits-while-ordering", junit);
  EXPECT_EQ(r.code, 3) << r.out;
  EXPECT_NE(r.out.find("orderer 'exits-while-ordering' called exit() while ordering: no verdict"), std::string::npos)
      << r.out;
  EXPECT_FALSE(std::filesystem::exists(junit));
}

TEST(FaultyPlugin, AnExceptionNamesTheOrderer) {
  const auto r = check("throws-while-ordering", "/dev/null");
  EXPECT_EQ(r.code, 2) << r.out;
  EXPECT_NE(r.out.find("orderer 'throws-while-ordering': the sorter's own failure"), std::string::npos) << r.out;
}
