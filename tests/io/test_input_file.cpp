// Reading inputs as regular files only (src/io/input_file.cpp): a FIFO, a
// device, a socket or a directory is refused at once with what it is, a name
// holding a NUL byte before anything is opened, and a file past the limit
// there; a regular file is read whole.
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/un.h>
#include <unistd.h>

#include "io/input_file.hpp"
#include "support/scratch_dir.hpp"

namespace pita::io {
namespace {

namespace fs = std::filesystem;

class InputFileTest : public ::testing::Test {
 protected:
  // The sentence read_regular_file's error gives for a "scene file".
  static std::string refusal(const fs::path& path, std::size_t limit = 1024) {
    try {
      (void)read_regular_file(path, limit);
    } catch (const InputError& error) {
      return error.sentence("scene file");
    }
    return "(read)";
  }

  test::ScratchDir scratch_;
  const fs::path& dir_ = scratch_.path();
};

TEST_F(InputFileTest, ReadsARegularFileWhole) {
  const std::string bytes("{\"a\": 1}\0tail", 13);
  std::ofstream(dir_ / "s.json", std::ios::binary) << bytes;
  EXPECT_EQ(read_regular_file(dir_ / "s.json", 13), bytes);
  EXPECT_EQ(refusal(dir_ / "s.json", 12), "the scene file is larger than the limit of 12 bytes");
}

TEST_F(InputFileTest, RefusesWhatIsNotARegularFileAtOnce) {
  ASSERT_EQ(::mkfifo((dir_ / "fifo").c_str(), 0600), 0);  // no writer: open() must not wait
  EXPECT_EQ(refusal(dir_ / "fifo"), "cannot read the scene file: it is a named pipe (FIFO), not a regular file");
  EXPECT_EQ(refusal("/dev/zero"), "cannot read the scene file: it is a device, not a regular file");
  EXPECT_EQ(refusal(dir_), "cannot read the scene file: it is a directory");
  EXPECT_EQ(refusal(dir_ / "missing"), "cannot open the scene file (No such file or directory)");
  // A symbolic link is what it leads to.
  fs::create_symlink("/dev/zero", dir_ / "zero.json");
  EXPECT_EQ(refusal(dir_ / "zero.json"), "cannot read the scene file: it is a device, not a regular file");
  const int listening = ::socket(AF_UNIX, SOCK_STREAM, 0);
  sockaddr_un address{};
  address.sun_family = AF_UNIX;
  const std::string socket_path = (dir_ / "sock").string();
  ASSERT_LT(socket_path.size(), sizeof address.sun_path);
  socket_path.copy(address.sun_path, socket_path.size());
  ASSERT_EQ(::bind(listening, reinterpret_cast<sockaddr*>(&address), sizeof address), 0);
  EXPECT_EQ(refusal(dir_ / "sock"), "cannot read the scene file: it is a socket, not a regular file");
  ::close(listening);
}

TEST_F(InputFileTest, ANameWithANulByteIsRefusedBeforeItIsOpened) {
  std::ofstream(dir_ / "secret.txt") << "{\"key\": \"secret\"}";
  const std::string name = (dir_ / "secret.txt").string() + std::string("\0.json", 6);
  EXPECT_EQ(refusal(name), "cannot read the scene file: its name holds a NUL byte");
}

}  // namespace
}  // namespace pita::io
