#include "sloshsph/io/vtk_writer.hpp"

#include <cstdint>
#include <cstring>
#include <sstream>

#include "sloshsph/io/files.hpp"

namespace sloshsph {
namespace {

// Appended-data block: a UInt64 byte count followed by the raw little-endian values.
struct Appended {
  std::string data;
  template <class T>
  std::size_t add(const std::vector<T>& values) {
    const std::size_t offset = data.size();
    const std::uint64_t bytes = values.size() * sizeof(T);
    data.append(reinterpret_cast<const char*>(&bytes), sizeof bytes);
    data.append(reinterpret_cast<const char*>(values.data()), bytes);
    return offset;
  }
};

}  // namespace

template <int D>
void write_vtu(const std::string& path, const BasicParticles<D>& p, bool include_walls) {
  const std::size_t n = include_walls ? p.size() : p.n_fluid;
  std::vector<float> points(3 * n), velocity(3 * n), pressure(n), density(n);
  std::vector<std::uint8_t> kind(n), types(n, 1);  // VTK_VERTEX
  std::vector<std::int32_t> id(n);
  std::vector<std::int64_t> connectivity(n), offsets(n);
  for (std::size_t i = 0; i < n; ++i) {
    for (int a = 0; a < D; ++a) {
      points[3 * i + a] = static_cast<float>(component(p.position[i], a));
      velocity[3 * i + a] = static_cast<float>(component(p.velocity[i], a));
    }
    pressure[i] = static_cast<float>(p.pressure[i]);
    density[i] = static_cast<float>(p.density[i]);
    kind[i] = p.is_fluid(i) ? 0 : 1;
    id[i] = p.id[i];
    connectivity[i] = static_cast<std::int64_t>(i);
    offsets[i] = static_cast<std::int64_t>(i + 1);
  }
  Appended a;
  const std::size_t o_vel = a.add(velocity), o_p = a.add(pressure), o_rho = a.add(density), o_kind = a.add(kind),
                    o_id = a.add(id), o_pts = a.add(points), o_con = a.add(connectivity), o_off = a.add(offsets),
                    o_typ = a.add(types);
  std::ostringstream x;
  x << "<?xml version=\"1.0\"?>\n"
    << "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n"
    << "  <UnstructuredGrid>\n"
    << "    <Piece NumberOfPoints=\"" << n << "\" NumberOfCells=\"" << n << "\">\n"
    << "      <PointData Scalars=\"pressure\" Vectors=\"velocity\">\n"
    << "        <DataArray type=\"Float32\" Name=\"velocity\" NumberOfComponents=\"3\" format=\"appended\" offset=\"" << o_vel << "\"/>\n"
    << "        <DataArray type=\"Float32\" Name=\"pressure\" format=\"appended\" offset=\"" << o_p << "\"/>\n"
    << "        <DataArray type=\"Float32\" Name=\"density\" format=\"appended\" offset=\"" << o_rho << "\"/>\n"
    << "        <DataArray type=\"UInt8\" Name=\"kind\" format=\"appended\" offset=\"" << o_kind << "\"/>\n"
    << "        <DataArray type=\"Int32\" Name=\"id\" format=\"appended\" offset=\"" << o_id << "\"/>\n"
    << "      </PointData>\n"
    << "      <Points>\n"
    << "        <DataArray type=\"Float32\" NumberOfComponents=\"3\" format=\"appended\" offset=\"" << o_pts << "\"/>\n"
    << "      </Points>\n"
    << "      <Cells>\n"
    << "        <DataArray type=\"Int64\" Name=\"connectivity\" format=\"appended\" offset=\"" << o_con << "\"/>\n"
    << "        <DataArray type=\"Int64\" Name=\"offsets\" format=\"appended\" offset=\"" << o_off << "\"/>\n"
    << "        <DataArray type=\"UInt8\" Name=\"types\" format=\"appended\" offset=\"" << o_typ << "\"/>\n"
    << "      </Cells>\n"
    << "    </Piece>\n"
    << "  </UnstructuredGrid>\n"
    << "  <AppendedData encoding=\"raw\">\n   _";
  std::string content = x.str();
  content += a.data;
  content += "\n  </AppendedData>\n</VTKFile>\n";
  write_file_atomic(path, content);
}

template void write_vtu<2>(const std::string&, const BasicParticles<2>&, bool);
template void write_vtu<3>(const std::string&, const BasicParticles<3>&, bool);

void PvdIndex::add(double time, const std::string& relative_file) {
  entries_.emplace_back(time, relative_file);
  std::ostringstream x;
  x.precision(10);
  x << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"1.0\" byte_order=\"LittleEndian\">\n  <Collection>\n";
  for (const auto& [t, f] : entries_) x << "    <DataSet timestep=\"" << t << "\" part=\"0\" file=\"" << f << "\"/>\n";
  x << "  </Collection>\n</VTKFile>\n";
  write_file_atomic(path_, x.str());
}

}  // namespace sloshsph
