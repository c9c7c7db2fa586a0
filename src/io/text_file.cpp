// Whole-file reads for the text readers (WKT, CSV): one read, errors as InvalidInput naming the file.
#include <pendepth/io.hpp>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <system_error>

namespace pendepth::io {

std::string read_text_file(const std::filesystem::path& path) {
  const std::string src = path.string();
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) throw InvalidInput(src + ": cannot read file (is a directory)");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InvalidInput(src + ": cannot read file (" + std::strerror(errno) + ")");
  in.seekg(0, std::ios::end);
  const std::streamoff size = in.tellg();
  in.seekg(0, std::ios::beg);
  std::string text(size > 0 ? static_cast<std::size_t>(size) : 0, '\0');
  if (size > 0 && !in.read(text.data(), size)) throw InvalidInput(src + ": cannot read file (read error)");
  return text;
}

}  // namespace pendepth::io
