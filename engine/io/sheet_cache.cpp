#include "engine/io/sheet_cache.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <new>
#include <vector>

#include "engine/io/atomic_file.hpp"
#include "engine/text/decimal.hpp"

namespace curvefold {
namespace {

constexpr char kMagic[8] = {'C', 'F', 'S', 'H', 'E', 'E', 'T', '1'};

// FNV-1a, 64 bits: two of them with different offsets make the 128-bit key and the checksum.
struct Fnv {
  std::uint64_t state;
  void add(const void* data, std::size_t size) {
    const auto* bytes = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < size; ++i) {
      state ^= bytes[i];
      state *= 0x100000001b3ull;
    }
  }
};

std::string hex(std::uint64_t value) {
  static const char* digits = "0123456789abcdef";
  std::string text(16, '0');
  for (int i = 15; i >= 0; --i, value >>= 4) text[i] = digits[value & 15];
  return text;
}

// The executable that folds: a rebuild must not read entries another build wrote.
std::string executableIdentity() {
  std::error_code error;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", error);
  struct stat info {};
  if (error || ::stat(self.c_str(), &info) != 0) return "unknown";
  return self.string() + ":" + std::to_string(info.st_size) + ":" +
         std::to_string(info.st_mtim.tv_sec) + "." + std::to_string(info.st_mtim.tv_nsec);
}

std::string keyOf(const Design& design) {
  static const std::string identity = executableIdentity();
  const std::string text = designText(design) + "\n" + identity;
  Fnv a{0xcbf29ce484222325ull}, b{0x84222325cbf29ce4ull};
  a.add(text.data(), text.size());
  b.add(text.data(), text.size());
  b.add(&a.state, sizeof a.state);
  return hex(a.state) + hex(b.state);
}

template <typename T>
void put(std::string& out, const T* data, std::size_t count) {
  if (count == 0) return;  // an empty vector's data() may be null
  out.append(reinterpret_cast<const char*>(data), count * sizeof(T));
}

template <typename T>
bool take(std::string_view& in, T* data, std::size_t count) {
  const std::size_t bytes = count * sizeof(T);
  if (in.size() < bytes) return false;
  if (count == 0) return true;  // an empty vector's data() may be null
  std::memcpy(static_cast<void*>(data), in.data(), bytes);
  in.remove_prefix(bytes);
  return true;
}

std::uint64_t checksum(std::string_view bytes) {
  Fnv fnv{0x9e3779b97f4a7c15ull};
  fnv.add(bytes.data(), bytes.size());
  return fnv.state;
}

}  // namespace

std::filesystem::path sheetCacheDirectory() {
  std::filesystem::path dir;
  if (const char* own = std::getenv("CURVEFOLD_CACHE_DIR"); own && *own)
    dir = own;
  else if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg)
    dir = std::filesystem::path(xdg) / "curvefold";
  else if (const char* home = std::getenv("HOME"); home && *home)
    dir = std::filesystem::path(home) / ".cache" / "curvefold";
  else
    return {};
  std::error_code error;
  std::filesystem::create_directories(dir, error);
  return error ? std::filesystem::path() : dir;
}

std::uint64_t sheetCacheBudget() {
  std::uint64_t budget = kSheetCacheBytes;
  if (const char* own = std::getenv("CURVEFOLD_CACHE_MAX_BYTES"); own && *own)
    if (std::uint64_t value = 0; readDecimal(own, value)) budget = value;
  return budget;
}

std::optional<Sheet> loadCachedSheet(const Design& design) {
  try {
    const std::filesystem::path dir = sheetCacheDirectory();
    if (dir.empty()) return std::nullopt;
    const std::string key = keyOf(design);
    const std::filesystem::path entry = dir / (key + ".sheet");
    // Never opened unless it is a regular file of a size the cache keeps.
    std::error_code error;
    if (!std::filesystem::is_regular_file(std::filesystem::symlink_status(entry, error)) ||
        std::filesystem::file_size(entry, error) > sheetCacheBudget() || error)
      return std::nullopt;
    std::ifstream file(entry, std::ios::binary);
    if (!file) return std::nullopt;
    const std::string bytes{std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>()};
    if (bytes.size() < sizeof kMagic + 32 + 8) return std::nullopt;
    std::string_view body(bytes.data(), bytes.size() - 8);
    std::uint64_t stored = 0;
    std::memcpy(&stored, bytes.data() + body.size(), 8);
    if (stored != checksum(body)) return std::nullopt;  // edited or cut short
    if (body.substr(0, sizeof kMagic) != std::string_view(kMagic, sizeof kMagic) ||
        body.substr(sizeof kMagic, 32) != key)
      return std::nullopt;
    body.remove_prefix(sizeof kMagic + 32);
    std::array<std::uint64_t, 3> counts{};
    if (!take(body, counts.data(), 3)) return std::nullopt;
    const std::uint64_t most = body.size();
    if (counts[0] > most / sizeof(glm::dvec3) || counts[1] > most / sizeof(Triangle) ||
        counts[2] > most / sizeof(TaggedEdge))
      return std::nullopt;
    Sheet sheet;
    sheet.positions.resize(counts[0]);
    sheet.development.resize(counts[0]);
    sheet.triangles.resize(counts[1]);
    sheet.tags.resize(counts[2]);
    if (!take(body, sheet.positions.data(), counts[0]) ||
        !take(body, sheet.development.data(), counts[0]) ||
        !take(body, sheet.triangles.data(), counts[1]) ||
        !take(body, sheet.tags.data(), counts[2]) || !body.empty())
      return std::nullopt;
    for (const Triangle& t : sheet.triangles)
      for (VertexIndex v : t)
        if (v >= counts[0]) return std::nullopt;
    // Used: the oldest entries are the ones evicted.
    std::filesystem::last_write_time(entry, std::filesystem::file_time_type::clock::now(), error);
    return sheet;
  } catch (const std::bad_alloc&) {
    // Not a bad entry: the process is out of memory, which the front end must hear of (its
    // reserve for the way out is spent on this failure; swallowed here, the next one aborts).
    throw;
  } catch (...) {
    return std::nullopt;
  }
}

void storeCachedSheet(const Design& design, const Sheet& sheet) noexcept {
  try {
    const std::filesystem::path dir = sheetCacheDirectory();
    if (dir.empty()) return;
    const std::string key = keyOf(design);
    std::string bytes(kMagic, sizeof kMagic);
    bytes += key;
    const std::array<std::uint64_t, 3> counts{sheet.positions.size(), sheet.triangles.size(),
                                              sheet.tags.size()};
    put(bytes, counts.data(), 3);
    put(bytes, sheet.positions.data(), sheet.positions.size());
    put(bytes, sheet.development.data(), sheet.development.size());
    put(bytes, sheet.triangles.data(), sheet.triangles.size());
    put(bytes, sheet.tags.data(), sheet.tags.size());
    const std::uint64_t sum = checksum(bytes);
    put(bytes, &sum, 1);
    const std::uint64_t budget = sheetCacheBudget();
    if (bytes.size() > budget) return;
    // Something else in an entry's place (a FIFO, a link) is replaced, never written through.
    const std::filesystem::path target = dir / (key + ".sheet");
    std::error_code error;
    const std::filesystem::file_status status = std::filesystem::symlink_status(target, error);
    if (std::filesystem::exists(status) && !std::filesystem::is_regular_file(status))
      std::filesystem::remove(target, error);
    writeFileAtomically(target, bytes);
    // Keep the newest few that fit the budget together; anything else named *.sheet goes.
    struct Entry {
      std::filesystem::file_time_type time;
      std::uint64_t size;
      std::filesystem::path path;
    };
    std::vector<Entry> entries;
    for (const auto& entry : std::filesystem::directory_iterator(dir)) {
      if (entry.path().extension() != ".sheet") continue;
      std::error_code error;
      const bool regular = entry.is_regular_file(error) && !entry.is_symlink(error);
      entries.push_back({entry.last_write_time(error),
                         regular ? entry.file_size(error) : budget + 1, entry.path()});
    }
    std::sort(entries.begin(), entries.end(),
              [](const Entry& a, const Entry& b) { return a.time > b.time; });
    std::uint64_t kept = 0;
    std::size_t count = 0;
    for (const Entry& entry : entries) {
      if (count < kSheetCacheEntries && entry.size <= budget - std::min(kept, budget)) {
        kept += entry.size;
        ++count;
        continue;
      }
      std::error_code ignored;
      std::filesystem::remove(entry.path, ignored);
    }
  } catch (...) {
    // A shortcut that could not be kept costs a replay next time, nothing else.
  }
}

Sheet buildSheetCached(const Design& design, std::string_view nameForErrors) {
  if (std::optional<Sheet> cached = loadCachedSheet(design)) return std::move(*cached);
  Sheet sheet = buildSheet(design, nameForErrors);
  storeCachedSheet(design, sheet);
  return sheet;
}

}  // namespace curvefold
