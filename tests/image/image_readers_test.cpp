// The readers on hostile and broken files: every one is refused with an error that
// names the file, and none allocates more than the file could hold.
#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <new>
#include <stdexcept>
#include <string>

#include "gi/image/image_io.hpp"

// The largest single allocation since `largest` was last reset: a reader that trusts
// a header claiming 30000 x 30000 pixels asks for gigabytes here.
namespace {
std::atomic<std::size_t> largest{0};
}
void* operator new(std::size_t size) {
  std::size_t seen = largest.load();
  while (size > seen && !largest.compare_exchange_weak(seen, size)) {
  }
  if (void* p = std::malloc(size ? size : 1)) return p;
  throw std::bad_alloc();
}
// Out of line, so that the compiler does not see `free` meet a pointer from `new` at a
// call site and warn of a mismatch: the pair above and below is the matched pair.
[[gnu::noinline]] void operator delete(void* p) noexcept { std::free(p); }
[[gnu::noinline]] void operator delete(void* p, std::size_t) noexcept { std::free(p); }

namespace {

namespace fs = std::filesystem;

fs::path write_file(const std::string& name, const std::string& bytes) {
  const fs::path file = fs::path(testing::TempDir()) / "gi_image_readers" / name;
  fs::create_directories(file.parent_path());
  std::ofstream(file, std::ios::binary) << bytes;
  return file;
}

// The message of what `read` throws for `file`, and the largest allocation it made.
template <class Read>
std::string refusal(Read read, const fs::path& file, std::size_t& allocated) {
  largest = 0;
  try {
    read(file);
  } catch (const std::runtime_error& e) {
    allocated = largest;
    const std::string message = e.what();
    EXPECT_NE(message.find(file.string()), std::string::npos) << "the error must name the file: " << message;
    return message;
  }
  allocated = largest;
  return "no error";
}

std::string pfm(const std::string& header, std::size_t pixel_bytes) { return header + std::string(pixel_bytes, '\0'); }

}  // namespace

TEST(ImageReaders, APfmHeaderClaimingGigabytesIsRefusedBeforeAllocating) {
  // 20 bytes that claim 30000 x 30000 pixels: 10.8 GB.
  const fs::path file = write_file("huge.pfm", "PF\n30000 30000\n-1\n  ");
  std::size_t allocated = 0;
  const std::string message = refusal(gi::read_pfm, file, allocated);
  EXPECT_NE(message.find("30000x30000"), std::string::npos) << message;
  EXPECT_NE(message.find("truncated"), std::string::npos) << message;
  EXPECT_LT(allocated, std::size_t(1) << 20) << "the reader allocated before checking the file's size";
}

TEST(ImageReaders, EveryBrokenPfmIsRefusedWithAReason) {
  const std::string good_header = "PF\n2 3\n-1\n";
  const struct {
    const char* name;
    std::string bytes;
    const char* expected;
  } cases[] = {
      {"empty", "", "no PF"},
      {"not_pfm", "P6\n2 3\n255\n", "no PF"},
      {"grey", pfm("Pf\n2 3\n-1\n", 24), "greyscale"},
      {"big_endian", pfm("PF\n2 3\n1\n", 72), "big-endian"},
      {"zero_width", pfm("PF\n0 3\n-1\n", 0), "width must be a whole number in [1, 32768]"},
      {"negative_width", pfm("PF\n-2 3\n-1\n", 72), "width must be"},
      {"wide", pfm("PF\n40000 1\n-1\n", 72), "width must be"},
      {"text_height", pfm("PF\n2 x\n-1\n", 72), "height must be"},
      {"nan_scale", pfm("PF\n2 3\nnan\n", 72), "scale"},
      {"zero_scale", pfm("PF\n2 3\n0\n", 72), "scale"},
      {"no_scale", "PF\n2 3\n", "no valid scale"},
      {"spaces", "PF\n" + std::string(100000, ' '), "no valid width"},
      {"long_field", "PF\n" + std::string(1000, '1'), "no valid width"},
      {"one_byte_short", pfm(good_header, 71), "truncated"},
      {"one_byte_long", pfm(good_header, 73), "the file has 83"},
  };
  for (const auto& c : cases) {
    std::size_t allocated = 0;
    const std::string message = refusal(gi::read_pfm, write_file(std::string(c.name) + ".pfm", c.bytes), allocated);
    EXPECT_NE(message.find(c.expected), std::string::npos) << c.name << ": " << message;
    EXPECT_LT(allocated, std::size_t(1) << 20) << c.name;
  }
  EXPECT_EQ(gi::read_pfm(write_file("good.pfm", pfm(good_header, 72))).width, 2);
}

TEST(ImageReaders, APfmCutAtAnyByteIsRefused) {
  gi::Image image(5, 4, gi::Pixel(0.5f, 2.0f, 1e6f));
  const fs::path whole = fs::path(testing::TempDir()) / "gi_image_readers" / "whole.pfm";
  gi::write_pfm(image, whole);
  std::ifstream in(whole, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  for (std::size_t length = 0; length < bytes.size(); ++length) {
    std::size_t allocated = 0;
    const std::string message = refusal(gi::read_pfm, write_file("cut.pfm", bytes.substr(0, length)), allocated);
    EXPECT_NE(message, "no error") << "cut at " << length;
  }
  EXPECT_EQ(gi::read_pfm(write_file("cut.pfm", bytes)).pixels, image.pixels);
}

TEST(ImageReaders, HdrAndPngHeadersClaimingMoreThanTheFileCanHoldAreRefused) {
  std::size_t allocated = 0;
  // A Radiance header for 30000 x 30000 pixels, and 8 bytes of data.
  const fs::path hdr = write_file("huge.hdr", "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 30000 +X 30000\n" +
                                                  std::string(8, '\x02'));
  std::string message = refusal(gi::read_hdr, hdr, allocated);
  EXPECT_NE(message.find("30000x30000"), std::string::npos) << message;
  EXPECT_LT(allocated, std::size_t(1) << 20);
  // A PNG signature and an IHDR chunk for 10000 x 10000 RGB pixels (stb does not
  // check chunk CRCs), and nothing else: 45 bytes cannot hold 10^8 pixels.
  std::string png = "\x89PNG\r\n\x1a\n";
  png += std::string("\0\0\0\x0dIHDR", 8) + std::string("\0\0\x27\x10\0\0\x27\x10\x08\x02\0\0\0", 13) +
         std::string(4, '\0');
  message = refusal(gi::read_png, write_file("huge.png", png), allocated);
  EXPECT_NE(message.find("10000x10000"), std::string::npos) << message;
  EXPECT_LT(allocated, std::size_t(1) << 20);
  message = refusal(gi::read_png, write_file("empty.png", ""), allocated);
  EXPECT_NE(message.find("not a PNG"), std::string::npos) << message;
  message = refusal(gi::read_hdr, fs::path(testing::TempDir()) / "gi_image_readers" / "missing.hdr", allocated);
  EXPECT_NE(message.find("cannot read"), std::string::npos) << message;
}
