#include "spott_text/file_reading.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <string>

namespace spott_text {
namespace {

std::string TempFile(const std::string& name, const std::string& bytes) {
  const std::string path = ::testing::TempDir() + name;
  std::ofstream(path, std::ios::binary) << bytes;
  return path;
}

TEST(ReadFileLimited, ReadsARegularTextFileWhole) {
  std::string error;
  const auto text = ReadTextFile(TempFile("world.yaml", "name: x\nrooms: []\n"), &error);
  ASSERT_TRUE(text) << error;
  EXPECT_EQ(*text, "name: x\nrooms: []\n");
}

TEST(ReadFileLimited, RefusesADeviceADirectoryAndAMissingFile) {
  std::string error;
  EXPECT_FALSE(ReadTextFile("/dev/zero", &error));
  EXPECT_NE(error.find("not a regular file"), std::string::npos) << error;
  EXPECT_FALSE(ReadTextFile("/tmp", &error));
  EXPECT_NE(error.find("not a regular file"), std::string::npos) << error;
  EXPECT_FALSE(ReadTextFile("/no/such/world.yaml", &error));
  EXPECT_NE(error.find("no such file"), std::string::npos) << error;
}

TEST(ReadFileLimited, RefusesAFileOverTheLimitNamingBothSizes) {
  std::string error;
  const std::string path = TempFile("big.bin", std::string(3u << 20, 'a'));
  EXPECT_FALSE(ReadFileLimited(path, 2u << 20, false, &error));
  EXPECT_EQ(error, "3 MB is over the limit of 2 MB");
  EXPECT_TRUE(ReadFileLimited(path, 3u << 20, false, &error)) << error;
}

TEST(ReadFileLimited, ATextFileWithANulByteIsRefusedABinaryOneIsRead) {
  std::string error;
  const std::string path = TempFile("nul.pgm", std::string("P5\n1 1\n255\n\0", 12));
  EXPECT_FALSE(ReadTextFile(path, &error));
  EXPECT_NE(error.find("NUL"), std::string::npos) << error;
  const auto bytes = ReadFileLimited(path, kMaxBinaryFileBytes, false, &error);
  ASSERT_TRUE(bytes) << error;
  EXPECT_EQ(bytes->size(), 12u);
}

}  // namespace
}  // namespace spott_text
