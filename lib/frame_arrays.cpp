#include "lib/frame_arrays.hpp"

#include <hdf5.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <string>
#include <type_traits>

#include "lib/atomic_file.hpp"

namespace tissu {
namespace {

static_assert(std::is_same_v<hid_t, std::int64_t>, "FrameArraysFile stores hid_t as int64_t");

/// Closes an HDF5 identifier when it goes out of scope.
class Handle {
 public:
  Handle(hid_t id, herr_t (*close)(hid_t)) : m_id(id), m_close(close) {}
  ~Handle() {
    if (m_id >= 0) m_close(m_id);
  }
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;
  hid_t get() const { return m_id; }

 private:
  hid_t m_id;
  herr_t (*m_close)(hid_t);
};

/// Why HDF5 refused `step`: the system's reason when a write failed (a full disk: "No space left
/// on device"), else the step.
std::string refusal(const char* step) {
  return errno != 0 ? std::string(std::strerror(errno)) : std::string("HDF5 refused ") + step;
}

/// Writes a scalar attribute `name` of `type` on `owner`.
void write_attribute(hid_t owner, const char* name, hid_t type, const void* value,
                     const std::filesystem::path& file) {
  const Handle space(H5Screate(H5S_SCALAR), H5Sclose);
  const Handle a(H5Acreate2(owner, name, type, space.get(), H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
  if (a.get() < 0 || H5Awrite(a.get(), type, value) < 0)
    throw FileWriteError(file, "arrays", refusal("an attribute"));
}

/// A fixed type and size for every per-frame array.
struct ArraySpec {
  const char* name;
  hid_t file_type;
  hid_t memory_type;
  hsize_t rows;
  hsize_t columns;  ///< 0 for a one-dimensional array
  const void* data;
};

}  // namespace

FrameArraysFile::FrameArraysFile(const std::filesystem::path& file, double frame_rate_hz,
                                 bool fixed_particles)
    : m_file(file) {
  // no library shutdown at exit: after a refused write (a full disk), HDF5 1.10's shutdown closes
  // the file again and crashes. Effective only before the library's first use; harmless after.
  H5dont_atexit();
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);  // errors become exceptions, not stderr dumps
  errno = 0;
  m_file_id = H5Fcreate(file.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  if (m_file_id < 0) throw FileWriteError(file, "arrays", refusal("to create the file"));
  try {
    auto attribute = [&](const char* name, hid_t type, const void* value) {
      write_attribute(m_file_id, name, type, value, m_file);
    };
    const Handle text(H5Tcopy(H5T_C_S1), H5Tclose);
    H5Tset_size(text.get(), H5T_VARIABLE);
    H5Tset_cset(text.get(), H5T_CSET_UTF8);
    const char* format = "tissu frames 1";
    attribute("format", text.get(), &format);
    attribute("frame_rate_hz", H5T_NATIVE_DOUBLE, &frame_rate_hz);
    const std::int8_t fixed = fixed_particles ? 1 : 0;
    attribute("fixed_particles", H5T_NATIVE_INT8, &fixed);
    m_frames_id = H5Gcreate2(m_file_id, "frames", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    if (m_frames_id < 0) throw FileWriteError(m_file, "arrays", refusal("the frames group"));
  } catch (...) {  // no destructor runs for a half-made object: close the file here
    H5Fclose(m_file_id);
    throw;
  }
}

FrameArraysFile::~FrameArraysFile() {
  if (m_frames_id >= 0) H5Gclose(m_frames_id);
  if (m_file_id >= 0) H5Fclose(m_file_id);
}

void FrameArraysFile::append(const ArrayFrame& frame) {
  const std::size_t n = frame.rest_m->size();
  if (static_cast<std::size_t>(frame.positions_m->size()) != 3 * n ||
      static_cast<std::size_t>(frame.velocities_m_per_s->size()) != 3 * n ||
      static_cast<std::size_t>(frame.masses_kg->size()) != n || frame.pinned->size() != n) {
    throw std::invalid_argument(
        "frame arrays " + m_file.string() +
        ": positions, velocities, rest positions, masses and pins disagree");
  }
  std::vector<double> rest(3 * n);
  for (std::size_t i = 0; i < n; ++i)
    for (int k = 0; k < 3; ++k) rest[3 * i + k] = (*frame.rest_m)[i][k];
  std::vector<std::int32_t> triangles;
  for (const std::vector<int>& face : *frame.faces) {
    if (face.size() != 3 && face.size() != 4)
      throw std::invalid_argument("frame arrays: a face of " + std::to_string(face.size()) +
                                  " vertices");
    triangles.insert(triangles.end(), {face[0], face[1], face[2]});
    if (face.size() == 4) triangles.insert(triangles.end(), {face[0], face[2], face[3]});
  }

  char name[16];
  std::snprintf(name, sizeof name, "%05d", frame.frame);
  errno = 0;
  try {
    write_group(name, frame, rest, triangles);
    if (H5Fflush(m_file_id, H5F_SCOPE_GLOBAL) < 0)
      throw FileWriteError(m_file, "arrays", refusal("to flush the file"));
  } catch (const FileWriteError&) {
    // best effort: a reader then finds only whole frames, if the disk takes the unlinking
    H5Ldelete(m_frames_id, name, H5P_DEFAULT);
    throw;
  }
}

void FrameArraysFile::write_group(const char* name, const ArrayFrame& frame,
                                  const std::vector<double>& rest,
                                  const std::vector<std::int32_t>& triangles) {
  const std::size_t n = rest.size() / 3;
  const Handle group(H5Gcreate2(m_frames_id, name, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
                     H5Gclose);
  if (group.get() < 0) throw FileWriteError(m_file, "arrays", refusal("a frame group"));
  const std::int32_t frame_number = frame.frame;
  write_attribute(group.get(), "frame", H5T_NATIVE_INT32, &frame_number, m_file);
  write_attribute(group.get(), "time_s", H5T_NATIVE_DOUBLE, &frame.time_s, m_file);

  const ArraySpec arrays[] = {
      {"positions", H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, n, 3, frame.positions_m->data()},
      {"velocities", H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, n, 3, frame.velocities_m_per_s->data()},
      {"rest_positions", H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, n, 3, rest.data()},
      {"masses", H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, n, 0, frame.masses_kg->data()},
      {"triangles", H5T_STD_I32LE, H5T_NATIVE_INT32, triangles.size() / 3, 3, triangles.data()},
      {"pinned", H5T_STD_U8LE, H5T_NATIVE_UINT8, n, 0, frame.pinned->data()},
  };
  for (const ArraySpec& a : arrays) {
    const hsize_t dims[2] = {a.rows, a.columns};
    const Handle space(H5Screate_simple(a.columns == 0 ? 1 : 2, dims, nullptr), H5Sclose);
    const Handle set(H5Dcreate2(group.get(), a.name, a.file_type, space.get(), H5P_DEFAULT,
                                H5P_DEFAULT, H5P_DEFAULT),
                     H5Dclose);
    if (set.get() < 0) throw FileWriteError(m_file, "arrays", refusal("a dataset"));
    if (a.rows > 0 && H5Dwrite(set.get(), a.memory_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, a.data) < 0)
      throw FileWriteError(m_file, "arrays", refusal("a dataset's values"));
  }
}

}  // namespace tissu
