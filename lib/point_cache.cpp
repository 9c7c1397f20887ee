#include "lib/point_cache.hpp"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iomanip>
#include <iterator>
#include <sstream>
#include <stdexcept>
#include <string>

namespace tissu {
namespace {

static_assert(sizeof(float) == 4, "PC2 stores float32");

/// `value`'s bytes, little-endian (tissu's targets are little-endian x86-64 and arm64).
template <class T>
void put(std::string& bytes, T value) {
  char raw[sizeof(T)];
  std::memcpy(raw, &value, sizeof(T));
  bytes.append(raw, sizeof(T));
}

constexpr long long samples_offset = 28;  ///< of the header's int32 sample count (bytes)
constexpr std::size_t header_bytes = 32;

/// The `T` stored little-endian at `offset` of `bytes`.
template <class T>
T get(const std::string& bytes, std::size_t offset) {
  T value;
  std::memcpy(&value, bytes.data() + offset, sizeof(T));
  return value;
}

}  // namespace

PointCacheFile::PointCacheFile(const std::filesystem::path& file, int points)
    : m_file(file, "point cache"), m_points(points) {
  std::string header("POINTCACHE2", 12);  // with its terminating NUL
  put<std::int32_t>(header, 1);           // version
  put<std::int32_t>(header, points);
  put<float>(header, 0.0f);  // start frame
  put<float>(header, 1.0f);  // one sample per frame
  put<std::int32_t>(header, 0);
  m_file.append(header);
}

void PointCacheFile::append(const Eigen::VectorXd& x) {
  if (x.size() != 3LL * m_points) {
    throw std::invalid_argument("point cache " + m_file.file().string() + ": " +
                                std::to_string(x.size() / 3) + " points, expected " +
                                std::to_string(m_points));
  }
  std::string sample;
  sample.reserve(static_cast<std::size_t>(x.size()) * sizeof(float));
  for (Eigen::Index k = 0; k < x.size(); ++k) put<float>(sample, static_cast<float>(x[k]));
  m_file.append(sample);
  std::string count;
  put<std::int32_t>(count, m_samples + 1);
  m_file.overwrite(samples_offset, count);
  ++m_samples;
}

PointCache read_point_cache(const std::filesystem::path& file, std::uintmax_t max_bytes) {
  const auto fail = [&](const std::string& what) {
    return PointCacheError("point cache " + file.string() + ": " + what);
  };
  std::error_code error;
  const std::uintmax_t size = std::filesystem::file_size(file, error);
  if (error || !std::filesystem::is_regular_file(file)) throw fail("cannot be opened");
  if (size > max_bytes) {
    throw fail(std::to_string(size) + " bytes, over the limit of " + std::to_string(max_bytes));
  }
  std::ifstream in(file, std::ios::binary);
  if (!in) throw fail("cannot be opened");
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (bytes.size() < header_bytes || bytes.compare(0, 12, std::string("POINTCACHE2", 12)) != 0) {
    throw fail("not a PC2 file: expected a 32-byte header starting \"POINTCACHE2\"");
  }
  const auto version = get<std::int32_t>(bytes, 12);
  if (version != 1) throw fail("version " + std::to_string(version) + "; expected 1");
  const auto points = get<std::int32_t>(bytes, 16);
  const auto samples = get<std::int32_t>(bytes, samples_offset);
  if (points <= 0 || samples <= 0) {
    throw fail(std::to_string(points) + " points and " + std::to_string(samples) +
               " samples; expected at least one of each");
  }
  PointCache cache;
  cache.start_frame = get<float>(bytes, 20);
  cache.sample_rate = get<float>(bytes, 24);
  if (!std::isfinite(cache.start_frame) || !(cache.sample_rate > 0.0) ||
      !std::isfinite(cache.sample_rate)) {
    throw fail("start frame " + std::to_string(cache.start_frame) + ", sample rate " +
               std::to_string(cache.sample_rate) +
               "; expected a finite start and a positive, finite sample rate");
  }
  const std::size_t sample_bytes = std::size_t{12} * static_cast<std::size_t>(points);
  // samples * sample_bytes can pass 2^64 (both counts up to 2^31 - 1): compared by division
  if (static_cast<std::size_t>(samples) > (bytes.size() - header_bytes) / sample_bytes) {
    std::ostringstream needed;  // in long double: what the counts ask can pass 2^64 bytes
    needed << std::fixed << std::setprecision(0)
           << header_bytes + static_cast<long double>(sample_bytes) * samples;
    throw fail("its header counts " + std::to_string(samples) + " samples of " +
               std::to_string(points) + " points (" + needed.str() + " bytes), but the file has " +
               std::to_string(bytes.size()) + " bytes");
  }
  cache.samples.resize(samples);
  for (std::int32_t k = 0; k < samples; ++k) {
    std::vector<Eigen::Vector3d>& sample = cache.samples[k];
    sample.resize(points);
    for (std::int32_t p = 0; p < points; ++p) {
      const std::size_t at = header_bytes + k * sample_bytes + std::size_t{12} * p;
      sample[p] = {get<float>(bytes, at), get<float>(bytes, at + 4), get<float>(bytes, at + 8)};
      if (!sample[p].allFinite()) {
        throw fail("sample " + std::to_string(k) + ", point " + std::to_string(p) +
                   ": a non-finite coordinate");
      }
    }
  }
  return cache;
}

}  // namespace tissu
