// write_file_atomically: whole content, umask's mode, no temporary left, one-line errors.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "harness/bench/atomic_file.h"
#include "harness/scene/input_error.h"

using namespace vob;
namespace fs = std::filesystem;

namespace {
fs::path scratch_dir() {
  const fs::path d = fs::temp_directory_path() / ("vob_atomic_test_" + std::to_string(getpid()));
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}
}  // namespace

TEST(AtomicFile, WritesWholeContentWithTheUmasksModeAndNoTemporary) {
  const fs::path d = scratch_dir();
  for (const mode_t mask : {mode_t(022), mode_t(077), mode_t(002)}) {
    const fs::path p = d / "sub" / "out.json";
    const mode_t old = umask(mask);
    write_file_atomically(p.string(), "first");
    write_file_atomically(p.string(), "second\n");  // replaces
    umask(old);
    std::ifstream in(p);
    std::stringstream s;
    s << in.rdbuf();
    EXPECT_EQ(s.str(), "second\n");
    struct stat st {};
    ASSERT_EQ(stat(p.c_str(), &st), 0);
    EXPECT_EQ(st.st_mode & 0777, 0666 & ~mask) << std::oct << mask;
  }
  for (const auto& e : fs::directory_iterator(d / "sub"))
    EXPECT_EQ(e.path().filename(), "out.json");  // no temporary left behind
}

TEST(AtomicFile, UnwritablePlaceIsOneLineInputError) {
  const fs::path d = scratch_dir();
  std::ofstream(d / "plain") << "x";
  EXPECT_THROW(write_file_atomically((d / "plain" / "out.json").string(), "x"), InputError);
  EXPECT_THROW(write_file_atomically(d.string(), "x"), InputError);  // a folder is in the way
  EXPECT_THROW(require_writable_folder((d / "plain" / "deeper").string()), InputError);
  EXPECT_NO_THROW(require_writable_folder((d / "not" / "yet").string()));
  EXPECT_FALSE(fs::exists(d / "not"));  // checked, not created
}
