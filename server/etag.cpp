#include "etag.h"

#include "raster/scene_fields.h"

#include <openssl/evp.h>

#include <array>
#include <cstring>
#include <memory>
#include <new>
#include <string>

namespace rasterd {
namespace {

// SHA-256 fed through a 64 KiB buffer: a scene is millions of small fields, and one EVP call per field
// would cost more than the hashing.
class Digest {
 public:
  Digest() : ctx_(EVP_MD_CTX_new(), EVP_MD_CTX_free) {
    if (!ctx_ || EVP_DigestInit_ex(ctx_.get(), EVP_sha256(), nullptr) != 1) throw std::bad_alloc();
  }
  void bytes(const void* data, std::size_t n) {
    if (n == 0) return;  // an empty vector's data() may be null, which memcpy must not get
    if (used_ + n > buffer_.size()) {
      flush();
      if (n > buffer_.size()) {
        EVP_DigestUpdate(ctx_.get(), data, n);
        return;
      }
    }
    std::memcpy(buffer_.data() + used_, data, n);
    used_ += n;
  }
  void operator()(const void* data, std::size_t n) { bytes(data, n); }
  std::array<unsigned char, 32> finish() {
    flush();
    std::array<unsigned char, 32> out{};
    unsigned int n = 0;
    EVP_DigestFinal_ex(ctx_.get(), out.data(), &n);
    return out;
  }

 private:
  void flush() {
    if (used_) EVP_DigestUpdate(ctx_.get(), buffer_.data(), used_);
    used_ = 0;
  }
  std::unique_ptr<EVP_MD_CTX, decltype(&EVP_MD_CTX_free)> ctx_;
  std::array<unsigned char, 1 << 16> buffer_;
  std::size_t used_ = 0;
};

}  // namespace

std::string scene_etag(const raster::Scene& scene, int render_version) {
  Digest d;
  // The render version, not the release: a tag names bytes, and only a change of render changes them.
  const std::string version = "rasterd render " + std::to_string(render_version);
  d.bytes(version.data(), version.size() + 1);  // with its NUL, so it cannot run into the scene's bytes
  // Every field of the parsed scene (raster/scene_fields.h, which fails the build when a field is left out).
  raster::write_canonical(scene, d);

  const auto hash = d.finish();
  static const char* hex = "0123456789abcdef";
  std::string tag = "\"";
  for (std::size_t i = 0; i < 16; ++i) tag += hex[hash[i] >> 4], tag += hex[hash[i] & 15];
  return tag + "\"";
}

std::string image_etag(std::string_view scene_tag, std::size_t png_bytes) {
  std::string tag(scene_tag.substr(0, scene_tag.size() - 1));  // without its closing quote
  return tag + "-" + std::to_string(png_bytes) + "\"";
}

NoneMatch none_match(std::string_view field, std::string_view scene_tag) {
  NoneMatch out;
  const std::string_view open = scene_tag.substr(0, scene_tag.size() - 1);  // '"' and the hash
  std::size_t at = 0;
  while (at < field.size()) {
    std::size_t end = field.find(',', at);
    if (end == std::string_view::npos) end = field.size();
    std::string_view item = field.substr(at, end - at);
    at = end + 1;
    while (!item.empty() && (item.front() == ' ' || item.front() == '\t')) item.remove_prefix(1);
    while (!item.empty() && (item.back() == ' ' || item.back() == '\t')) item.remove_suffix(1);
    if (item.starts_with("W/")) item.remove_prefix(2);
    if (item == "*" || item == scene_tag) {
      out.hit = true;
      continue;
    }
    // "<hash>-<length>": the hash this scene's, the length a decimal number of at most 15 digits.
    if (!item.starts_with(open) || item.size() < open.size() + 3 || item[open.size()] != '-' ||
        item.back() != '"')
      continue;
    const std::string_view digits = item.substr(open.size() + 1, item.size() - open.size() - 2);
    if (digits.empty() || digits.size() > 15 ||
        digits.find_first_not_of("0123456789") != std::string_view::npos)
      continue;
    out.hit = true;
    out.png_bytes = std::stoull(std::string(digits));
  }
  return out;
}

}  // namespace rasterd
