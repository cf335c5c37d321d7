#pragma once
// --dump-tess: every tessellated vertex (patch id, gl_TessCoord, position, normal), streamed to a
// file chunk by chunk in the draw's order (patch order, then generation order within a patch).
//
// Binary format (any file name not ending in .txt), little-endian:
//   header, 16 bytes: "TESSDUMP" (8 bytes), uint32 version = 1, uint32 record size = 40
//   records, 40 bytes each: uint32 patch_id, float32 tess_coord[3], float32 position[3],
//                           float32 normal[3]   (position and normal in world space)
// Text format (*.txt): a '#' header line naming the columns, then one record per line,
//   "patch_id u v w px py pz nx ny nz", floats printed with %.9g (they round-trip exactly).
#include <cstdint>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "stages/tess_stage.h"

namespace tessref {

class TessDumpWriter {
 public:
  // Throws InputError when the file cannot be created.
  explicit TessDumpWriter(const std::string& path);
  void write(const std::vector<TessDumpRecord>& records);
  // Flushes and closes; throws InputError on a write error (disk full).
  void close();
  std::size_t records_written() const { return count_; }
  std::uint64_t bytes_written() const { return bytes_; }  // header included
  bool text() const { return text_; }

  // The size of a dump of `records` records: exact for binary files; for text, an estimate from
  // an average line (the default scene's lines average 111 bytes; 100 is used, so that an
  // estimate refuses no dump that would fit).
  static std::uint64_t estimated_bytes(std::uint64_t records, bool text);

 private:
  std::string path_;
  bool text_ = false;
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> file_{nullptr, &std::fclose};
  std::size_t count_ = 0;
  std::uint64_t bytes_ = 0;
};

// A scene of draws keeps gl_Position in a dump's records, as the user's outputs mean nothing to
// tessref: position = clip.xyz, normal = (clip.w, 0, 0).
std::vector<TessDumpRecord> as_clip_records(std::vector<TessDumpRecord> records);

// Reads a binary dump back (InputError naming the file when it is not one, or is cut short).
std::vector<TessDumpRecord> read_tess_dump(const std::string& path);

}  // namespace tessref
