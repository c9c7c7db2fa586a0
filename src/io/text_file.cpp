// Whole-file reads for the readers (WKT, CSV, OBJ, OFF, STL): the stream is read to its end, so
// pipes, FIFOs, /dev/stdin and process substitutions work like regular files (no size asked, no
// seek); errors are InvalidInput naming the file.
#include <pendepth/io.hpp>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <istream>
#include <system_error>

namespace pendepth::io {

std::string read_stream(std::istream& in, std::string_view source, std::size_t size_hint) {
  std::string text;
  text.reserve(size_hint);
  constexpr std::size_t kBlock = std::size_t(1) << 16;
  for (;;) {
    const std::size_t old = text.size();
    const std::size_t want = std::max(kBlock, text.capacity() - old);  // the whole hint at once
    text.resize(old + want);
    in.read(text.data() + old, static_cast<std::streamsize>(want));
    text.resize(old + static_cast<std::size_t>(in.gcount()));
    if (!in) break;
  }
  if (in.bad() || !in.eof())
    throw InvalidInput(std::string(source) + ": cannot read file (read error" +
                       (errno ? std::string(": ") + std::strerror(errno) : std::string()) + ")");
  return text;
}

std::string read_text_file(const std::filesystem::path& path) {
  const std::string src = path.string();
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) throw InvalidInput(src + ": cannot read file (is a directory)");
  errno = 0;
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InvalidInput(src + ": cannot read file (" + std::strerror(errno ? errno : ENOENT) + ")");
  // A regular file's size is only a hint for the first allocation: FIFOs and character devices
  // have none, and a file may grow or shrink while it is read.
  std::size_t hint = 0;
  if (std::filesystem::is_regular_file(path, ec)) {
    const std::uintmax_t size = std::filesystem::file_size(path, ec);
    if (!ec && size < (std::uintmax_t(1) << 40)) hint = static_cast<std::size_t>(size) + 1;
  }
  errno = 0;
  return read_stream(in, src, hint);
}

}  // namespace pendepth::io
