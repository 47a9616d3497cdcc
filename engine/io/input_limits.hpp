// What the readers accept, checked before anything is allocated for it (README "Limits"). Each
// is far above what a real design, recording or script holds, and each refusal is one line naming
// the file and the limit, so a huge or hostile input never costs gigabytes or ends in an abort.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

namespace curvefold {

// A design with a 200k-triangle embedded mesh is about 15 MiB.
inline constexpr std::uint64_t kMaxDesignBytes = 64ull << 20;
// A recording's header embeds a design's surface; a frame line is about 250 bytes; 256 MiB is
// more than three hours at 90 Hz.
inline constexpr std::uint64_t kMaxRecordingBytes = 256ull << 20;
inline constexpr std::uint64_t kMaxRecordingHeaderBytes = kMaxDesignBytes;
inline constexpr std::uint64_t kMaxRecordingFrameBytes = 64ull << 10;

// Crease patterns from other tools (docs/formats.md "Crease patterns"): a FOLD or SVG file, the
// vertices and edges it may hold (counted as read, and again after an SVG's lines are split where
// they cross), and a FOLD file's face corners (all faces together). Origami Simulator's largest
// example has about 10k edges; a 1M-vertex sheet is the simulation's largest target.
inline constexpr std::uint64_t kMaxCreasePatternBytes = 64ull << 20;
inline constexpr std::uint64_t kMaxCreasePatternVertices = 1'000'000;
inline constexpr std::uint64_t kMaxCreasePatternEdges = 3'000'000;
inline constexpr std::uint64_t kMaxCreasePatternFaceCorners = 6'000'000;
// One SVG attribute value or text: libxml2's limit without XML_PARSE_HUGE (XML_MAX_TEXT_LENGTH).
inline constexpr std::uint64_t kMaxSvgTokenBytes = 10'000'000;

// The whole file as text, refused (FileError) when it cannot be read, is not a regular file (a
// folder, a FIFO, a device: notRegularFile), or holds more than maxBytes: "<path>: 104857600 bytes,
// more than a <kind> may hold (64 MiB)". Out of memory while reading is the same kind of one-line
// FileError.
std::string readWholeFile(const std::filesystem::path& path, std::uint64_t maxBytes,
                          std::string_view kind);

// The message for an input over a limit.
std::string tooLarge(std::string_view name, std::uint64_t bytes, std::uint64_t maxBytes,
                     std::string_view kind);

}  // namespace curvefold
