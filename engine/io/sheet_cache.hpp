// A cache of folded sheets, so that a command-line `fold` or `export` costs one fold rather than
// a replay of the design's whole history (issue 13, E23: 6.8 s per call at 59 folds).
//
// Entries are addressed by content: the key is a 128-bit hash of the design's canonical text (its
// surface and every fold, as saveDesign writes them) and of the running executable (its path,
// size and modification time), so an entry is found for any file holding that history and is
// never used by another build, whose folds might differ. Each entry carries a checksum of its
// bytes: a stale, truncated or edited entry is a miss, never trusted. Entries live in
// $CURVEFOLD_CACHE_DIR, else $XDG_CACHE_HOME/curvefold, else ~/.cache/curvefold; the oldest go
// when there are more than kSheetCacheEntries or they hold more than kSheetCacheBytes together
// ($CURVEFOLD_CACHE_MAX_BYTES sets another budget); a sheet larger than the budget is not kept.
// Only regular files are read (a FIFO put there would block the open). The cache is only ever a
// shortcut: every failure to read or write it is silent and costs the replay.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include "engine/geometry/sheet.hpp"
#include "engine/io/design_document.hpp"

namespace curvefold {

inline constexpr std::size_t kSheetCacheEntries = 16;
// About six sheets of a million triangles (80 MB each).
inline constexpr std::uint64_t kSheetCacheBytes = std::uint64_t(512) << 20;

// kSheetCacheBytes, or $CURVEFOLD_CACHE_MAX_BYTES when it is a whole number.
std::uint64_t sheetCacheBudget();

// The folder entries go to, or empty when there is none (no HOME, an unwritable folder).
std::filesystem::path sheetCacheDirectory();

// The cached sheet of exactly this design, or nothing (a missing or damaged entry). Throws
// std::bad_alloc when memory runs out while reading one: that is no bad entry.
std::optional<Sheet> loadCachedSheet(const Design& design);
// Stores the sheet of this design (best effort; never throws).
void storeCachedSheet(const Design& design, const Sheet& sheet) noexcept;

// buildSheet through the cache: a hit costs reading the entry, a miss the replay (then stored).
Sheet buildSheetCached(const Design& design, std::string_view nameForErrors);

}  // namespace curvefold
