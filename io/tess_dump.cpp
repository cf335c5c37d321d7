#include "io/tess_dump.h"

#include <bit>
#include <cstdint>
#include <cstring>
#include <cerrno>

#include "common/error.h"

namespace tessref {
namespace {

static_assert(std::endian::native == std::endian::little, "the dump format is little-endian");

constexpr std::uint64_t kBinaryHeaderBytes = 16, kBinaryRecordBytes = 40, kTextRecordBytes = 100;

bool ends_with(const std::string& s, const std::string& suffix) {
  return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

}  // namespace

TessDumpWriter::TessDumpWriter(const std::string& path)
    : path_(path), text_(ends_with(path, ".txt")), file_(std::fopen(path.c_str(), "wb"), &std::fclose) {
  if (!file_) throw InputError(path + ": cannot create the tessellation dump: " + std::strerror(errno));
  if (text_) {
    static const char kHeader[] = "# tessref tess dump v1: patch_id u v w px py pz nx ny nz\n";
    std::fputs(kHeader, file_.get());
    bytes_ = sizeof kHeader - 1;
  } else {
    const std::uint32_t version = 1, record_size = 40;
    std::fwrite("TESSDUMP", 1, 8, file_.get());
    std::fwrite(&version, 4, 1, file_.get());
    std::fwrite(&record_size, 4, 1, file_.get());
    bytes_ = kBinaryHeaderBytes;
  }
}

void TessDumpWriter::write(const std::vector<TessDumpRecord>& records) {
  std::FILE* f = file_.get();
  for (const TessDumpRecord& r : records) {
    if (text_) {
      bytes_ += std::uint64_t(std::fprintf(f, "%u %.9g %.9g %.9g %.9g %.9g %.9g %.9g %.9g %.9g\n", r.patch_id,
                   double(r.tess_coord.x), double(r.tess_coord.y), double(r.tess_coord.z),
                   double(r.position.x), double(r.position.y), double(r.position.z),
                   double(r.normal.x), double(r.normal.y), double(r.normal.z)));
      continue;
    }
    unsigned char rec[40];
    std::memcpy(rec, &r.patch_id, 4);
    std::memcpy(rec + 4, &r.tess_coord, 12);
    std::memcpy(rec + 16, &r.position, 12);
    std::memcpy(rec + 28, &r.normal, 12);
    std::fwrite(rec, 1, sizeof rec, f);
    bytes_ += sizeof rec;
  }
  count_ += records.size();
}

std::uint64_t TessDumpWriter::estimated_bytes(std::uint64_t records, bool text) {
  return text ? 56 + records * kTextRecordBytes : kBinaryHeaderBytes + records * kBinaryRecordBytes;
}

void TessDumpWriter::close() {
  if (!file_) return;
  const bool failed = std::ferror(file_.get()) != 0;
  const bool close_failed = std::fclose(file_.release()) != 0;
  if (failed || close_failed) throw InputError(path_ + ": error writing the tessellation dump");
}

std::vector<TessDumpRecord> read_tess_dump(const std::string& path) {
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> f(std::fopen(path.c_str(), "rb"), &std::fclose);
  if (!f) throw InputError(path + ": cannot open the tessellation dump: " + std::strerror(errno));
  char magic[8];
  std::uint32_t header[2];
  if (std::fread(magic, 1, 8, f.get()) != 8 || std::memcmp(magic, "TESSDUMP", 8) != 0 ||
      std::fread(header, 4, 2, f.get()) != 2 || header[0] != 1 || header[1] != kBinaryRecordBytes)
    throw InputError(path + ": not a binary tessellation dump (version 1, 40-byte records)");
  std::vector<TessDumpRecord> records;
  unsigned char rec[kBinaryRecordBytes];
  std::size_t n;
  while ((n = std::fread(rec, 1, sizeof rec, f.get())) == sizeof rec) {
    TessDumpRecord r;
    std::memcpy(&r.patch_id, rec, 4);
    std::memcpy(&r.tess_coord, rec + 4, 12);
    std::memcpy(&r.position, rec + 16, 12);
    std::memcpy(&r.normal, rec + 28, 12);
    records.push_back(r);
  }
  if (n != 0) throw InputError(path + ": the tessellation dump ends in the middle of a record");
  return records;
}

std::vector<TessDumpRecord> as_clip_records(std::vector<TessDumpRecord> records) {
  for (TessDumpRecord& r : records) {
    r.position = glm::vec3(r.clip);
    r.normal = glm::vec3(r.clip.w, 0.0f, 0.0f);
  }
  return records;
}

}  // namespace tessref
