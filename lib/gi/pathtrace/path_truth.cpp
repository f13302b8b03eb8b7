#include "gi/pathtrace/reference.hpp"

#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>

#include "gi/core/atomic_file.hpp"
#include "gi/image/image_io.hpp"

namespace gi {

namespace {

// FNV-1a over the bytes of each value fed in.
struct Fingerprint {
  std::uint64_t hash = 0xcbf29ce484222325ULL;
  void add(const void* data, std::size_t size) {
    const auto* bytes = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < size; ++i) hash = (hash ^ bytes[i]) * 0x100000001b3ULL;
  }
  void add(double x) { add(&x, sizeof x); }
  void add(const vec3& v) { add(v.x), add(v.y), add(v.z); }
  std::string hex() const {
    std::ostringstream os;
    os << std::hex;
    os.width(16);
    os.fill('0');
    os << hash;
    return os.str();
  }
};

std::filesystem::path with_suffix(const std::filesystem::path& stem, const std::string& suffix) {
  return stem.parent_path() / (stem.filename().string() + suffix);
}

// Each block's mean, or (of a picture of standard errors) the standard error of that
// mean: its pixels' errors are independent, so sqrt(sum se^2) / block^2.
enum class Over { Means, Errors };
Image over_blocks(const Image& image, int block, Over what) {
  Image out(image.width / block, image.height / block);
  for (int y = 0; y < out.height; ++y)
    for (int x = 0; x < out.width; ++x) {
      glm::dvec3 sum(0.0);
      for (int j = 0; j < block; ++j)
        for (int i = 0; i < block; ++i) {
          const glm::dvec3 v(image.at(x * block + i, y * block + j));
          sum += what == Over::Means ? v : v * v;
        }
      out.at(x, y) = Pixel((what == Over::Means ? sum : glm::sqrt(sum)) / double(block * block));
    }
  return out;
}

// sqrt(mean over values with r above the cut of (a / r)^2).
double relative_rms(const Image& a, const Image& r) {
  double total = 0;
  for (const Pixel& p : r.pixels) total += (double(p.x) + p.y + p.z) / 3;
  const double cut = 1e-3 * total / double(r.pixels.size());  // 1e-3 of the mean
  double sum = 0;
  long long count = 0;
  for (std::size_t i = 0; i < r.pixels.size(); ++i)
    for (int c = 0; c < 3; ++c)
      if (r.pixels[i][c] > cut) {
        const double q = double(a.pixels[i][c]) / r.pixels[i][c];
        sum += q * q;
        ++count;
      }
  return count ? std::sqrt(sum / double(count)) : 0.0;
}

void check_block(const Image& image, int block) {
  if (block < 1 || image.width % block || image.height % block)
    throw std::invalid_argument("the block size must divide the image's width and height");
}

}  // namespace

std::string reference_fingerprint(const PathScene& scene, const PathSettings& settings, int width, int height) {
  const Scene& s = scene.scene();
  Fingerprint f;
  for (const Material& m : s.materials) {
    for (const Color& c : {m.diffuse, m.mirror, m.transmission, m.emission, m.checker_diffuse}) f.add(c);
    f.add(m.ior), f.add(m.checker_size);
  }
  for (const Sphere& x : s.spheres) f.add(x.center), f.add(x.radius), f.add(double(x.material));
  for (const Plane& x : s.planes) f.add(x.point), f.add(x.normal), f.add(double(x.material));
  for (const Quad& x : s.quads) f.add(x.corner), f.add(x.edge_u), f.add(x.edge_v), f.add(double(x.material));
  for (const Triangle& x : s.triangles) f.add(x.a), f.add(x.b), f.add(x.c), f.add(double(x.material));
  f.add(s.background);
  f.add(s.camera.eye), f.add(s.camera.look_at), f.add(s.camera.up), f.add(s.camera.vertical_fov);
  f.add(double(width)), f.add(double(height)), f.add(double(settings.max_depth));
  return f.hex();
}

PathReference reference_from_film(const Film& film, const std::string& scene, const std::string& fingerprint,
                                  std::uint64_t seed, const PathSettings& settings, double seconds) {
  PathReference r{scene, fingerprint, film_mean(film), film_variance(film), film.samples, seed, 1, settings, seconds};
  for (Pixel& p : r.standard_error.pixels) p = glm::sqrt(p);
  return r;
}

void save_reference(const PathReference& r, const std::filesystem::path& stem) {
  const std::filesystem::path text = with_suffix(stem, ".txt");
  if (!stem.parent_path().empty()) std::filesystem::create_directories(stem.parent_path());
  std::filesystem::remove(text);  // the set is invalid until the new text file is in place
  write_pfm(r.mean, with_suffix(stem, ".pfm"));  // each file whole or not at all (atomic_file.hpp)
  write_pfm(r.standard_error, with_suffix(stem, "_stderr.pfm"));
  write_atomically(text, [&](std::ostream& out) {
    out << "# A path-traced reference (gi/pathtrace/reference.hpp): mean in .pfm, standard error in _stderr.pfm\n"
        << "scene " << r.scene << "\nfingerprint " << r.fingerprint << "\nwidth " << r.mean.width << "\nheight "
        << r.mean.height << "\nspp " << r.spp << "\nseed " << r.seed << "\nbatches " << r.batches << "\nstrategy "
        << name(r.settings.strategy) << "\nmax_depth " << r.settings.max_depth << "\nroulette_depth "
        << r.settings.roulette_depth << "\nseconds " << r.seconds << "\nrelative_standard_error_per_pixel "
        << relative_standard_error(r, 1) << '\n';
    for (int block : {4, 8, 16})
      if (r.mean.width % block == 0 && r.mean.height % block == 0)
        out << "relative_standard_error_" << block << "x" << block << "_blocks " << relative_standard_error(r, block)
            << '\n';
  });
}

std::optional<PathReference> load_reference(const std::filesystem::path& stem, const std::string& fingerprint,
                                            std::string* why) {
  const auto refuse = [&](const std::string& reason) -> std::optional<PathReference> {
    if (why) *why = reason;
    return std::nullopt;
  };
  const std::filesystem::path text = with_suffix(stem, ".txt");
  std::error_code error;
  if (!std::filesystem::is_regular_file(text, error)) return refuse("no file " + text.string());
  // The text is a few hundred bytes; one a hostile hand made large is refused unread.
  if (std::filesystem::file_size(text, error) > 1 << 16 || error) return refuse(text.string() + " is too large");
  std::ifstream in(text);
  if (!in) return refuse("cannot read " + text.string());
  std::map<std::string, std::string> fields;
  for (std::string line; std::getline(in, line) && fields.size() < 100;) {
    if (line.empty() || line[0] == '#') continue;
    const std::size_t space = line.find(' ');
    if (space == std::string::npos) return refuse(text.string() + ": a line without a value");
    fields[line.substr(0, space)] = line.substr(space + 1);
  }
  PathReference r;
  try {
    r.scene = fields.at("scene");
    r.fingerprint = fields.at("fingerprint");
    const int width = std::stoi(fields.at("width")), height = std::stoi(fields.at("height"));
    r.spp = std::stoll(fields.at("spp"));
    r.seed = std::stoull(fields.at("seed"));
    r.batches = std::stoi(fields.at("batches"));
    r.settings.strategy = strategy_from_name(fields.at("strategy"));
    r.settings.max_depth = std::stoi(fields.at("max_depth"));
    r.settings.roulette_depth = std::stoi(fields.at("roulette_depth"));
    r.seconds = std::stod(fields.at("seconds"));
    if (r.fingerprint != fingerprint)
      return refuse(text.string() + " was made for another scene, size or depth limit (or by other code)");
    if (width < 1 || height < 1 || width > 16384 || height > 16384 || r.spp < 2)
      return refuse(text.string() + ": size or sample count out of range");
    // The files must hold exactly the pixels announced, before anything is allocated.
    const auto expected_bytes = static_cast<std::uintmax_t>(width) * height * sizeof(Pixel);
    for (const char* suffix : {".pfm", "_stderr.pfm"}) {
      const std::filesystem::path file = with_suffix(stem, suffix);
      const std::uintmax_t size = std::filesystem::file_size(file, error);
      if (error || size < expected_bytes || size > expected_bytes + 64)
        return refuse(file.string() + " is missing or not " + std::to_string(width) + "x" + std::to_string(height));
    }
    r.mean = read_pfm(with_suffix(stem, ".pfm"));
    r.standard_error = read_pfm(with_suffix(stem, "_stderr.pfm"));
    if (r.mean.width != width || r.mean.height != height || !r.mean.same_size(r.standard_error))
      return refuse(stem.string() + ": the pictures' sizes do not match " + text.string());
    // Radiance and its standard error are finite and not negative: a damaged file
    // must not turn into a garbage error figure.
    for (const Image* image : {&r.mean, &r.standard_error})
      for (const Pixel& p : image->pixels)
        if (!(p.x >= 0 && p.y >= 0 && p.z >= 0 && std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z)))
          return refuse(stem.string() + ": a pixel is negative or not a number");
  } catch (const std::out_of_range&) {
    return refuse(text.string() + ": a field is missing or out of range");
  } catch (const std::exception& e) {
    return refuse(text.string() + ": " + e.what());
  }
  return r;
}

PathReference combine(const PathReference& a, const PathReference& b) {
  if (a.fingerprint != b.fingerprint || !a.mean.same_size(b.mean))
    throw std::invalid_argument("combine: the references are of different pictures");
  PathReference r = a;
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

double relative_rms_error(const Image& test, const Image& reference, int block) {
  if (!test.same_size(reference)) throw std::invalid_argument("relative RMS error: the images differ in size");
  check_block(reference, block);
  const Image t = over_blocks(test, block, Over::Means), r = over_blocks(reference, block, Over::Means);
  Image difference(t.width, t.height);
  for (std::size_t i = 0; i < t.pixels.size(); ++i) difference.pixels[i] = t.pixels[i] - r.pixels[i];
  return relative_rms(difference, r);
}

double relative_standard_error(const PathReference& reference, int block) {
  check_block(reference.mean, block);
  return relative_rms(over_blocks(reference.standard_error, block, Over::Errors),
                      over_blocks(reference.mean, block, Over::Means));
}

PathReference downsample(const PathReference& reference, int factor) {
  check_block(reference.mean, factor);
  PathReference r = reference;
  r.mean = over_blocks(reference.mean, factor, Over::Means);
  r.standard_error = over_blocks(reference.standard_error, factor, Over::Errors);
  return r;
}

}  // namespace gi
