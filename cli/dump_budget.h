#pragma once
// How large `render --dump-tess` may grow: --max-dump-bytes, and never more than the free space
// where the dump goes, less room for the images written to the same file system.
#include <cstdint>
#include <string>
#include <vector>

#include "io/tess_dump.h"

namespace tessref::cli {

class DumpBudget {
 public:
  // max_dump_bytes 0: no --max-dump-bytes. image_paths: the images the render writes; those on the
  // dump's file system are given room for image_bytes each (their size uncompressed).
  DumpBudget(const std::string& dump_path, std::uint64_t max_dump_bytes,
             const std::vector<std::string>& image_paths = {}, std::uint64_t image_bytes = 0);

  // Before drawing, where fixed levels and the built-in programs fix the size: InputError with the
  // size when the dump would pass the limit.
  void check_estimate(std::uint64_t tes_invocations, bool text) const;
  // While drawing, where control shaders or adaptive levels choose the levels: InputError once the
  // dump has passed the limit.
  void check_written(const TessDumpWriter& dump) const;

 private:
  std::string path_;
  std::uint64_t max_dump_bytes_ = 0, limit_ = UINT64_MAX;
  std::string bound_;  // which bound limit_ is, for messages
};

}  // namespace tessref::cli
