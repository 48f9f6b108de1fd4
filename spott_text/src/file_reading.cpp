#include "spott_text/file_reading.h"

#include <filesystem>
#include <fstream>
#include <iterator>

namespace spott_text {

namespace {

std::string Megabytes(std::uintmax_t bytes) {
  return std::to_string((bytes + (1u << 20) - 1) >> 20) + " MB";
}

}  // namespace

std::optional<std::string> ReadFileLimited(const std::string& path, std::uintmax_t max_bytes,
                                           bool text, std::string* error) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);  // follows links
  if (ec || !fs::exists(status)) {
    *error = "no such file";
    return std::nullopt;
  }
  if (!fs::is_regular_file(status)) {
    *error = "not a regular file (a directory, device or pipe is not read)";
    return std::nullopt;
  }
  const std::uintmax_t size = fs::file_size(path, ec);
  if (ec) {
    *error = "cannot read its size: " + ec.message();
    return std::nullopt;
  }
  if (size > max_bytes) {
    *error = Megabytes(size) + " is over the limit of " + Megabytes(max_bytes);
    return std::nullopt;
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    *error = "cannot open";
    return std::nullopt;
  }
  std::string bytes;
  bytes.reserve(static_cast<std::size_t>(size));
  // At most max_bytes + 1 even if the file grew since its size was read.
  std::istreambuf_iterator<char> it(in), end;
  for (; it != end && bytes.size() <= max_bytes; ++it) bytes.push_back(*it);
  if (bytes.size() > max_bytes) {
    *error = "grew over the limit of " + Megabytes(max_bytes) + " while read";
    return std::nullopt;
  }
  if (text && bytes.find('\0') != std::string::npos) {
    *error = "not a text file (it holds a NUL byte)";
    return std::nullopt;
  }
  return bytes;
}

}  // namespace spott_text
