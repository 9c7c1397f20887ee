#include "lib/point_cache.hpp"

#include <cstdint>
#include <cstring>
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

}  // namespace tissu
