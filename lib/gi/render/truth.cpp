#include "gi/render/truth.hpp"

#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "gi/core/atomic_file.hpp"
#include "gi/core/hash.hpp"
#include "gi/core/timer.hpp"
#include "gi/image/image_io.hpp"

namespace gi {

namespace {

namespace fs = std::filesystem;

const char* const format_line = "truth 1";

fs::path with_suffix(const fs::path& stem, const std::string& suffix) {
  return stem.parent_path() / (stem.filename().string() + suffix);
}

// FNV-1a of the whole file, read in blocks; empty if the file cannot be read.
std::string file_checksum(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) return "";
  std::uint64_t h = fnv1a("");
  std::string block(1 << 16, '\0');
  while (in.read(block.data(), static_cast<std::streamsize>(block.size())) || in.gcount() > 0)
    h = fnv1a(std::string_view(block.data(), static_cast<std::size_t>(in.gcount())), h);
  return hex(h);
}

// Lines the text holds that are not the truth's settings: derived when it is written.
bool derived(const std::string& name) { return name.starts_with("relative_standard_error"); }

std::string text_of(const Truth& t) {
  std::ostringstream out;
  out << "# The truth other pictures are scored against (gi/render/truth.hpp): mean in .pfm, standard error in "
         "_stderr.pfm\n"
      << format_line << "\nfingerprint " << t.fingerprint << "\ncode " << t.code << "\nwidth " << t.mean.width
      << "\nheight " << t.mean.height << "\nspp " << t.spp << "\nseed " << t.seed << "\nbatches " << t.batches
      << "\nseconds " << t.seconds << '\n';
  for (const auto& [name, value] : t.about) out << name << ' ' << value << '\n';
  if (t.spp >= 2) {
    out << "relative_standard_error_per_pixel " << relative_standard_error(t.standard_error, t.mean, 1) << '\n';
    for (int block : {4, 8, 16})
      if (t.mean.width % block == 0 && t.mean.height % block == 0)
        out << "relative_standard_error_" << block << "x" << block << "_blocks " << relative_standard_error(t.standard_error, t.mean, block)
            << '\n';
  }
  return out.str();
}

// Why the pictures cannot be a truth, or "".
std::string implausible(const Truth& t) {
  for (const Image* image : {&t.mean, &t.standard_error})
    for (const Pixel& p : image->pixels)
      for (int c = 0; c < 3; ++c)
        if (!(p[c] >= 0 && std::isfinite(p[c]))) return "a pixel is negative or not a number";
  bool measured = false, below = false;
  for (std::size_t i = 0; i < t.mean.pixels.size(); ++i)
    for (int c = 0; c < 3; ++c) {
      measured = measured || t.standard_error.pixels[i][c] > 0;
      below = below || t.standard_error.pixels[i][c] < t.mean.pixels[i][c];
    }
  if (measured && !below) return "its standard error is no smaller than its mean anywhere: noise, not a truth";
  return "";
}

}  // namespace

std::string Truth::about_value(const std::string& name) const {
  for (const auto& [n, value] : about)
    if (n == name) return value;
  return "";
}

Truth truth_from_film(const Film& film, const TruthKey& key, std::uint64_t seed, double seconds,
                      std::vector<std::pair<std::string, std::string>> about) {
  if (film.width != key.width || film.height != key.height)
    throw std::invalid_argument("truth: the film is not the key's size");
  return {key.fingerprint, key.code, film_mean(film), film_standard_error(film), film.samples, seed, 1, seconds,
          std::move(about), {}};
}

std::vector<fs::path> truth_files(const fs::path& stem) {
  return {with_suffix(stem, ".txt"), with_suffix(stem, ".pfm"), with_suffix(stem, "_stderr.pfm")};
}

bool truth_files_exist(const fs::path& stem) {
  std::error_code error;
  for (const fs::path& file : truth_files(stem))
    if (fs::exists(file, error)) return true;
  return false;
}

void save_truth(const Truth& t, const fs::path& stem) {
  if (!t.mean.same_size(t.standard_error)) throw std::invalid_argument("truth: mean and standard error differ in size");
  const fs::path text = with_suffix(stem, ".txt");
  if (!stem.parent_path().empty()) fs::create_directories(stem.parent_path());
  fs::remove(text);  // the set is invalid until the new text file is in place
  write_pfm(t.mean, with_suffix(stem, ".pfm"));  // each file whole or not at all (atomic_file.hpp)
  write_pfm(t.standard_error, with_suffix(stem, "_stderr.pfm"));
  std::string body = text_of(t);
  body += "mean_fnv1a " + file_checksum(with_suffix(stem, ".pfm")) + "\nstderr_fnv1a " +
          file_checksum(with_suffix(stem, "_stderr.pfm")) + '\n';
  body += "text_fnv1a " + hex(fnv1a(body)) + '\n';
  write_atomically(text, [&](std::ostream& out) { out << body; });
}

std::optional<Truth> load_truth(const fs::path& stem, const TruthKey& key, std::string* why) {
  const fs::path text_file = with_suffix(stem, ".txt");
  const auto refuse = [&](const std::string& reason) -> std::optional<Truth> {
    if (why) *why = text_file.string() + ": " + reason;
    return std::nullopt;
  };
  std::error_code error;
  if (!fs::is_regular_file(text_file, error)) return refuse("no such file");
  // The text is a few hundred bytes; one a hostile hand made large is refused unread.
  if (fs::file_size(text_file, error) > 1 << 16 || error) return refuse("too large to be a truth's text");
  std::ifstream in(text_file, std::ios::binary);
  std::ostringstream whole;
  whole << in.rdbuf();
  const std::string text = whole.str();
  const std::size_t sum_at = text.rfind("\ntext_fnv1a ");
  if (!in || sum_at == std::string::npos) return refuse("no checksum of its text (not a truth, or damaged)");
  if (text.substr(sum_at + 1) != "text_fnv1a " + hex(fnv1a(std::string_view(text).substr(0, sum_at + 1))) + "\n")
    return refuse("its text fails its checksum (damaged or edited)");

  Truth t;
  std::string mean_sum, stderr_sum;
  int width = 0, height = 0;
  bool format = false;
  try {
    std::istringstream lines(text.substr(0, sum_at + 1));
    for (std::string line; std::getline(lines, line);) {
      if (line.empty() || line[0] == '#') continue;
      const std::size_t space = line.find(' ');
      if (space == std::string::npos) return refuse("a line without a value");
      const std::string name = line.substr(0, space), value = line.substr(space + 1);
      if (name + ' ' + value == format_line) format = true;
      else if (name == "fingerprint") t.fingerprint = value;
      else if (name == "code") t.code = value;
      else if (name == "width") width = std::stoi(value);
      else if (name == "height") height = std::stoi(value);
      else if (name == "spp") t.spp = std::stoll(value);
      else if (name == "seed") t.seed = std::stoull(value);
      else if (name == "batches") t.batches = std::stoi(value);
      else if (name == "seconds") t.seconds = std::stod(value);
      else if (name == "mean_fnv1a") mean_sum = value;
      else if (name == "stderr_fnv1a") stderr_sum = value;
      else if (!derived(name)) t.about.emplace_back(name, value);
    }
  } catch (const std::exception&) {
    return refuse("a number that does not read");
  }
  if (!format || mean_sum.empty() || stderr_sum.empty()) return refuse("not a truth's text (a line is missing)");
  if (width != key.width || height != key.height)
    return refuse("it is " + std::to_string(width) + "x" + std::to_string(height) + ", not " +
                  std::to_string(key.width) + "x" + std::to_string(key.height));
  if (t.fingerprint != key.fingerprint) return refuse("it was made for another scene or other settings");
  if (key.code != "any" && t.code != key.code) return refuse("it was made by other library code");
  if (t.spp < 1 || t.batches < 1) return refuse("its sample count is out of range");
  // The pictures must hold exactly the pixels announced, before anything is allocated.
  const auto expected_bytes = static_cast<std::uintmax_t>(width) * height * sizeof(Pixel);
  for (const auto& [suffix, sum] : {std::pair{".pfm", mean_sum}, std::pair{"_stderr.pfm", stderr_sum}}) {
    const fs::path file = with_suffix(stem, suffix);
    const std::uintmax_t size = fs::file_size(file, error);
    if (error || size < expected_bytes || size > expected_bytes + 64)
      return refuse(file.filename().string() + " is missing or not " + std::to_string(width) + "x" +
                    std::to_string(height));
    if (file_checksum(file) != sum) return refuse(file.filename().string() + " fails its checksum (damaged or edited)");
  }
  try {
    t.mean = read_pfm(with_suffix(stem, ".pfm"));
    t.standard_error = read_pfm(with_suffix(stem, "_stderr.pfm"));
  } catch (const std::exception& e) {
    return refuse(std::string("a picture does not read: ") + e.what());
  }
  if (t.mean.width != width || t.mean.height != height || !t.mean.same_size(t.standard_error))
    return refuse("the pictures' sizes do not match the text");
  if (const std::string wrong = implausible(t); !wrong.empty()) return refuse(wrong);
  return t;
}

Score score(const Image& picture, const Truth& truth) {
  return {picture_error(picture, truth.mean, truth.mask), reference_noise(truth.standard_error, truth.mean, truth.mask),
          {}};
}

Score score(const Film& film, const Truth& truth) {
  Score s = score(film_mean(film), truth);
  s.own_noise = reference_noise(film_standard_error(film), truth.mean, truth.mask);
  return s;
}

Truth combine(const Truth& a, const Truth& b) {
  if (a.fingerprint != b.fingerprint || !a.mean.same_size(b.mean))
    throw std::invalid_argument("combine: the truths are of different pictures");
  Truth r = a;
  const double na = double(a.spp), nb = double(b.spp), n = na + nb;
  for (std::size_t i = 0; i < a.mean.pixels.size(); ++i) {
    const glm::dvec3 ma(a.mean.pixels[i]), mb(b.mean.pixels[i]);
    const glm::dvec3 sa(a.standard_error.pixels[i]), sb(b.standard_error.pixels[i]);
    const glm::dvec3 m2 = sa * sa * na * (na - 1) + sb * sb * nb * (nb - 1) + (mb - ma) * (mb - ma) * (na * nb / n);
    r.mean.pixels[i] = Pixel((na * ma + nb * mb) / n);
    r.standard_error.pixels[i] = Pixel(glm::sqrt(m2 / (n * (n - 1))));
  }
  r.spp = a.spp + b.spp;
  r.batches = a.batches + b.batches;
  r.seed = std::min(a.seed, b.seed);
  r.seconds = a.seconds + b.seconds;
  return r;
}

Truth downsample(const Truth& truth, int factor) {
  Truth r = truth;
  r.mean = block_means(truth.mean, factor);
  r.standard_error = block_standard_errors(truth.standard_error, factor);
  return r;
}

CachedTruth cached_truth(const fs::path& stem, const TruthKey& key, std::uint64_t seed,
                         const std::function<Film(const std::string& reason)>& render,
                         const std::vector<std::pair<std::string, std::string>>& about) {
  CachedTruth result;
  result.stem = stem;
  std::string why;
  if (auto kept = load_truth(stem, key, &why)) {
    result.truth = std::move(*kept);
    result.from_cache = true;
    return result;
  }
  result.reason = truth_files_exist(stem) ? why : "none kept";
  const Timer timer;
  const Film film = render(result.reason);
  result.truth = truth_from_film(film, key, seed, timer.seconds(), about);
  save_truth(result.truth, stem);
  return result;
}

}  // namespace gi
