#include "gi/raytrace/reference.hpp"

#include <cstdio>
#include <fstream>
#include <sstream>

#include "gi/core/atomic_file.hpp"
#include "gi/core/hash.hpp"
#include "gi/image/image_io.hpp"

namespace gi {

namespace {

namespace fs = std::filesystem;

const char* const format_line = "gi-workbench reference cache 1";

std::string exact(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.17g", v);
  return buffer;
}

// FNV-1a of the whole file, read in blocks; empty if the file cannot be read.
std::string checksum(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) return "";
  std::uint64_t h = fnv1a("");
  std::string block(1 << 16, '\0');
  while (in.read(block.data(), static_cast<std::streamsize>(block.size())) || in.gcount() > 0)
    h = fnv1a(std::string_view(block.data(), static_cast<std::size_t>(in.gcount())), h);
  return hex(h);
}

std::string whole_file(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return in ? text.str() : "";
}

// The image, if `folder` holds one for exactly this key; else why not.
std::string try_read(const fs::path& pfm, const fs::path& key_file, const std::string& key, int width, int height,
                     Image& image) {
  std::error_code error;
  if (!fs::exists(pfm, error) && !fs::exists(key_file, error)) return "no cached image";
  // The key file is small; one a hostile hand made large is refused unread.
  if (fs::file_size(key_file, error) > 1 << 16 || error) return "its key file is missing or too large";
  const std::string stored = whole_file(key_file);
  if (stored.compare(0, key.size(), key) != 0) {
    // The first two lines are the format and the code; the rest are the settings.
    const std::size_t code_end = key.find('\n', key.find('\n') + 1) + 1;
    const bool same_settings = stored.size() > code_end && stored.compare(code_end, key.size() - code_end, key, code_end) == 0;
    return same_settings ? "the cached image was made by other library code"
                         : "the cached image was made with other settings";
  }
  std::istringstream rest(stored.substr(key.size()));
  std::string size_word, sum_word, sum;
  std::uintmax_t size = 0;
  if (!(rest >> size_word >> size >> sum_word >> sum) || size_word != "pfm_bytes" || sum_word != "pfm_fnv1a")
    return "its key file is damaged";
  if (fs::file_size(pfm, error) != size || error) return "the cached image has the wrong size";
  if (checksum(pfm) != sum) return "the cached image fails its checksum";
  try {
    image = read_pfm(pfm);
  } catch (const std::exception& e) {
    return std::string("the cached image cannot be read: ") + e.what();
  }
  return image.width == width && image.height == height ? "" : "the cached image has the wrong size";
}

// Everything but the code: what names the file, so that a change of code replaces
// the file instead of adding one.
std::string settings_text(const World& world, const RenderSettings& s, std::uint64_t seed, const std::string& scene_key) {
  std::ostringstream key;
  key << "scene " << scene_key
      << "\nacceleration " << name(world.acceleration) << "\nwidth " << s.width << "\nheight " << s.height
      << "\nmax_depth " << s.trace.max_depth << "\nmin_contribution " << exact(s.trace.min_contribution)
      << "\nepsilon " << exact(s.trace.epsilon) << "\nshadow_sampling "
      << light_sampling_name(s.trace.soft_shadows.sampling) << "\nshadow_n " << s.trace.soft_shadows.n
      << "\nsampler " << sampler_name(s.sampling.sampler) << "\nsampler_n " << s.sampling.n << "\nthreshold "
      << exact(s.sampling.threshold) << "\nmax_subdivisions " << s.sampling.max_subdivisions << "\nseed " << seed
      << '\n';
  return key.str();
}

}  // namespace

std::string reference_key(const World& world, const RenderSettings& settings, std::uint64_t seed,
                          const std::string& scene_key) {
  return std::string(format_line) + "\ncode " + render_code_fingerprint() + "\n" +
         settings_text(world, settings, seed, scene_key);
}

CachedImage cached_reference(const World& world, const RenderSettings& settings, std::uint64_t seed, int threads,
                             const std::string& scene_key, const fs::path& folder) {
  const std::string key = reference_key(world, settings, seed, scene_key);
  const std::string stem = "reference_" + hex(fnv1a(settings_text(world, settings, seed, scene_key)));
  CachedImage result;
  result.file = folder / (stem + ".pfm");
  const fs::path key_file = folder / (stem + ".key");
  result.reason = try_read(result.file, key_file, key, settings.width, settings.height, result.image);
  if (result.reason.empty()) {
    result.from_cache = true;
    return result;
  }
  result.image = render(world, settings, seed, threads).image;
  write_pfm(result.image, result.file);
  const std::string sum = checksum(result.file);
  const std::uintmax_t size = fs::file_size(result.file);
  write_atomically(key_file, [&](std::ostream& out) { out << key << "pfm_bytes " << size << "\npfm_fnv1a " << sum << '\n'; });
  return result;
}

}  // namespace gi
