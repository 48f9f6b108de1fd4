// Reading a user's file with limits (issue 21): a world, a program, a plan, a mission or a map
// image is read only from a regular file (not a device, a FIFO or a directory) of at most a few
// megabytes, so `/dev/zero` or a wrong path to a video never exhausts memory.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

namespace spott_text {

/// The largest text file read (a world of the project is under 100 kB).
constexpr std::uintmax_t kMaxTextFileBytes = 16u << 20;
/// The largest binary file read (a map_server image: 8,000 x 8,000 cells of 4 bytes).
constexpr std::uintmax_t kMaxBinaryFileBytes = 256u << 20;

/// The file's bytes, or nothing with the reason in `error` ("not a regular file", "17 MB is
/// over the limit of 16 MB", "cannot open"). With `text`, a file holding a NUL byte is refused.
std::optional<std::string> ReadFileLimited(const std::string& path, std::uintmax_t max_bytes,
                                           bool text, std::string* error);

/// ReadFileLimited for a text file of at most kMaxTextFileBytes.
inline std::optional<std::string> ReadTextFile(const std::string& path, std::string* error) {
  return ReadFileLimited(path, kMaxTextFileBytes, true, error);
}

}  // namespace spott_text
