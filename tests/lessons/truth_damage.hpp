#pragma once
// The ways a truth's files (render/truth.hpp) come to be wrong, for the tests that check
// every lesson refuses them: the error picture copied over the mean, one pixel set to
// 1e30, every pixel 1e-3, a picture cut in half, a byte of the text flipped.
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "gi/image/image_io.hpp"
#include "lesson_run.hpp"

namespace gi_test {

inline const std::vector<std::string> truth_damages = {"stderr over the mean", "one pixel 1e30",
                                                      "every pixel 1e-3", "a truncated picture", "a flipped byte"};

// Copies the truth at `from` (three files) to `to`.
inline void copy_truth(const std::filesystem::path& from, const std::filesystem::path& to) {
  std::filesystem::create_directories(to.parent_path());
  for (const char* suffix : {".txt", ".pfm", "_stderr.pfm"})
    std::filesystem::copy_file(from.string() + suffix, to.string() + suffix,
                               std::filesystem::copy_options::overwrite_existing);
}

inline void damage_truth(const std::filesystem::path& stem, const std::string& how) {
  const std::string mean = stem.string() + ".pfm", error = stem.string() + "_stderr.pfm", text = stem.string() + ".txt";
  if (how == "stderr over the mean") {
    std::filesystem::copy_file(error, mean, std::filesystem::copy_options::overwrite_existing);
  } else if (how == "one pixel 1e30" || how == "every pixel 1e-3") {
    gi::Image picture = gi::read_pfm(mean);
    for (gi::Pixel& p : picture.pixels) {
      p = gi::Pixel(how == "one pixel 1e30" ? 1e30f : 1e-3f);
      if (how == "one pixel 1e30") break;
    }
    gi::write_pfm(picture, mean);
  } else if (how == "a truncated picture") {
    std::filesystem::resize_file(mean, std::filesystem::file_size(mean) / 2);
  } else if (how == "a flipped byte") {
    std::string bytes = gi_test::bytes(text);
    bytes[bytes.size() / 2] ^= 1;
    std::ofstream(text, std::ios::binary) << bytes;
  }
}

}  // namespace gi_test
