#include "verify/feedback_compare.h"

#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>

#include "common/error.h"

namespace tessref {
namespace {

std::vector<std::byte> read_bytes(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError(file.string() + ": cannot read the capture's transform feedback buffer");
  const std::vector<char> chars((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::vector<std::byte> bytes(chars.size());
  std::memcpy(bytes.data(), chars.data(), chars.size());
  return bytes;
}

std::string word_text(const std::vector<std::byte>& bytes, std::size_t word) {
  if (4 * word + 4 > bytes.size()) return "nothing";
  std::uint32_t u = 0;
  float f = 0.0f;
  std::memcpy(&u, bytes.data() + 4 * word, 4);
  std::memcpy(&f, &u, 4);
  char buf[48];
  std::snprintf(buf, sizeof buf, "0x%08x (%.9g)", u, double(f));
  return buf;
}

}  // namespace

FeedbackComparison compare_feedback(const std::filesystem::path& capture, const nlohmann::json& manifest,
                                    const std::vector<FeedbackBuffers>& mine) {
  FeedbackComparison out;
  if (!manifest.contains("transform_feedback")) return out;
  for (const nlohmann::json& entry : manifest["transform_feedback"]) {
    const std::size_t draw = entry.at("draw").get<std::size_t>();
    const FeedbackBuffers* own = nullptr;
    for (const FeedbackBuffers& f : mine)
      if (f.draw == draw) own = &f;
    const std::uint64_t primitives = entry.at("primitives").get<std::uint64_t>();
    if (!own) {
      out.failures.push_back("transform feedback: draw " + std::to_string(draw) + " recorded nothing in tessref");
      continue;
    }
    if (own->primitives != primitives)
      out.failures.push_back("transform feedback: draw " + std::to_string(draw) + ": the driver wrote " +
                             std::to_string(primitives) + " primitives, tessref " + std::to_string(own->primitives));
    bool streams = false;  // primitives on a geometry shader's streams past 0
    if (entry.contains("stream_primitives"))
      for (std::size_t s = 1; s < 4; ++s) {
        const std::uint64_t theirs = entry["stream_primitives"].at(s).get<std::uint64_t>();
        streams = streams || theirs || own->stream_primitives[s];
        if (theirs != own->stream_primitives[s])
          out.failures.push_back("transform feedback: draw " + std::to_string(draw) + ": the driver wrote " +
                                 std::to_string(theirs) + " points on vertex stream " + std::to_string(s) + ", tessref " +
                                 std::to_string(own->stream_primitives[s]));
      }
    const nlohmann::json& files = entry.at("files");
    for (std::size_t b = 0; b < files.size(); ++b) {
      const std::vector<std::byte> theirs = read_bytes(capture / files[b].get<std::string>());
      const std::vector<std::byte> ours = b < own->bytes.size() ? own->bytes[b] : std::vector<std::byte>{};
      std::size_t first = 0;
      while (first < theirs.size() && first < ours.size() && theirs[first] == ours[first]) ++first;
      // With several streams the capture cannot tell which one a buffer records, and reads it as
      // far as the longest could fill it: past tessref's bytes it must hold the zeros it was given.
      std::size_t tail = ours.size();
      if (streams && first == ours.size())
        while (tail < theirs.size() && theirs[tail] == std::byte{0}) ++tail;
      const bool identical = first == ours.size() && (streams ? tail == theirs.size() : theirs.size() == ours.size());
      if (!identical && first == ours.size() && streams) first = tail;
      nlohmann::json r = {{"draw", draw}, {"buffer", b}, {"driver_bytes", identical ? ours.size() : theirs.size()},
                          {"tessref_bytes", ours.size()}, {"identical", identical}};
      if (!identical) {
        // The vertex and word there, from tessref's vertex size in this buffer.
        const std::size_t vertices = std::size_t(own->primitives) * std::size_t(std::max(own->corners, 1));
        const std::size_t stride = vertices ? ours.size() / vertices : 0;
        const std::size_t word = first / 4;
        r["first_difference_byte"] = first;
        std::string where = "byte " + std::to_string(first);
        if (stride) where += " (vertex " + std::to_string(first / stride) + ", word " + std::to_string((first % stride) / 4) + ")";
        out.failures.push_back("transform feedback: draw " + std::to_string(draw) + " buffer " + std::to_string(b) +
                               " differs from " + where + ": driver " + word_text(theirs, word) + ", tessref " +
                               word_text(ours, word) + "; " + std::to_string(theirs.size()) + " and " +
                               std::to_string(ours.size()) + " bytes");
      }
      out.report.push_back(r);
    }
  }
  return out;
}

}  // namespace tessref
