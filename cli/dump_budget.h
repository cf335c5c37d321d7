#pragma once
// How large `render --dump-tess` may grow: --max-dump-bytes, and never more than the free space
// where the dump goes (less 64 MiB for the images written beside it).
#include <cstdint>
#include <string>

#include "io/tess_dump.h"

namespace tessref::cli {

class DumpBudget {
 public:
  DumpBudget(const std::string& dump_path, std::uint64_t max_dump_bytes);  // 0: no --max-dump-bytes

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
