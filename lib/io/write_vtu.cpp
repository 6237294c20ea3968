// The .vtu file: VTK's XML UnstructuredGrid with its arrays as raw binary
// "appended data", so that writing a large mesh is copying memory, not
// formatting numbers.  The XML head lists every array with its byte offset
// into the appended section; that section is '_' followed by each array as
// a 64-bit byte count and the values, in the machine's byte order (which
// the head names), last array first (put_head says why).  The triangles are
// read from the mesh once per array that needs them (connectivity, each
// attribute, angles, areas) rather than copied into memory, which would
// cost the most at the moment memory use peaks.
//
// VTK numbers points from 0 whatever the run's base.  Six-node triangles
// are VTK_QUADRATIC_TRIANGLE, whose midpoints come in the order (0,1),
// (1,2), (2,0); Triangle's order is the midpoint opposite each corner.

#include <array>
#include <bit>
#include <cstdint>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <gpdr/errors.hpp>
#include <gpdr/mesh_formats.hpp>

#include "io/output_file.hpp"

namespace gpdr::io {
namespace {

using File = OutputTransaction::File;

// Values appended to the file a few thousand at a time.
template <class T>
class Appender {
public:
    explicit Appender(File& file) : file_(file) {}
    ~Appender() = default;
    Appender(const Appender&) = delete;
    Appender& operator=(const Appender&) = delete;

    void push(T v) {
        values_[n_++] = v;
        if (n_ == values_.size()) flush();
    }
    void flush() {
        file_.append(values_.data(), n_ * sizeof(T));
        n_ = 0;
    }

private:
    File& file_;
    std::array<T, 8192> values_;
    std::size_t n_ = 0;
};

// One DataArray: where it goes in the head, how many bytes it has, and how
// its values are appended.
struct Array {
    enum class Section { point_data, cell_data, points, cells };
    Section section;
    std::string name;
    const char* type;
    unsigned components;
    std::uint64_t bytes;
    std::function<void(File&)> append;
};

// Calls f(corners, attributes) on each triangle, in the file's order.
template <class F>
void for_each_triangle(const MeshExport& mesh, F&& f) {
    EleSource source = mesh.triangles();
    std::vector<double> attributes(source.attribute_count);
    std::uint32_t c[6];
    for (std::size_t t = 0; t < source.count; ++t) {
        source.next(c, attributes.data());
        f(c, attributes.data());
    }
}

// The connectivity in VTK's corner order, as integers of type I.
template <class I>
void append_connectivity(File& file, const MeshExport& mesh) {
    static constexpr int vtk_order[6] = {0, 1, 2, 5, 3, 4};
    const std::uint32_t nc = mesh.corners_per_triangle;
    Appender<I> out(file);
    for_each_triangle(mesh, [&](const std::uint32_t* c, const double*) {
        for (std::uint32_t k = 0; k < nc; ++k) out.push(static_cast<I>(c[vtk_order[k]]));
    });
    out.flush();
}

// A value of type T per triangle: f(corners, attributes).
template <class T>
void append_per_triangle(File& file, const MeshExport& mesh,
                         const std::function<double(const std::uint32_t*, const double*)>& f) {
    Appender<T> out(file);
    for_each_triangle(mesh, [&](const std::uint32_t* c, const double* attributes) {
        out.push(static_cast<T>(f(c, attributes)));
    });
    out.flush();
}

// The vertices' markers and attributes (PointData).
void add_point_data(std::vector<Array>& arrays, const NodeSet& nodes, const WriteFormat& format) {
    const std::uint64_t n = nodes.size();
    if (format.markers && nodes.has_markers())
        arrays.push_back(
            {Array::Section::point_data, "boundary_marker", "Int32", 1, 4 * n, [&nodes](File& f) {
                 static_assert(sizeof(int) == 4);
                 f.append(nodes.markers.data(), nodes.markers.size() * sizeof(int));
             }});
    for (std::uint32_t a = 0; a < nodes.attribute_count; ++a)
        arrays.push_back({Array::Section::point_data, fmt::format("attribute_{}", a), "Float64", 1,
                          8 * n, [&nodes, a](File& f) {
                              Appender<double> out(f);
                              const std::size_t na = nodes.attribute_count;
                              for (std::size_t v = 0; v < nodes.size(); ++v)
                                  out.push(nodes.attributes[v * na + a]);
                              out.flush();
                          }});
}

// The triangles' attributes, smallest angles and areas (CellData).
void add_cell_data(std::vector<Array>& arrays, const MeshExport& mesh) {
    const std::uint64_t m = mesh.triangle_count;
    using S = Array::Section;
    for (std::uint32_t a = 0; a < mesh.attribute_count; ++a)
        arrays.push_back({S::cell_data, fmt::format("region_attribute_{}", a), "Float64", 1, 8 * m,
                          [&mesh, a](File& f) {
                              append_per_triangle<double>(
                                  f, mesh, [a](const std::uint32_t*, const double* attributes) {
                                      return attributes[a];
                                  });
                          }});
    // The angles and areas are derived, for looking at the mesh rather than
    // for computing with: single precision (7 digits) makes the file a
    // sixth smaller.
    const double* xy = mesh.nodes->xy.data();
    arrays.push_back({S::cell_data, "min_angle", "Float32", 1, 4 * m, [&mesh, xy](File& f) {
                          append_per_triangle<float>(
                              f, mesh, [xy](const std::uint32_t* c, const double*) {
                                  return smallest_angle_degrees(xy + 2 * std::size_t{c[0]},
                                                                xy + 2 * std::size_t{c[1]},
                                                                xy + 2 * std::size_t{c[2]});
                              });
                      }});
    arrays.push_back(
        {S::cell_data, "area", "Float32", 1, 4 * m, [&mesh, xy](File& f) {
             append_per_triangle<float>(f, mesh, [xy](const std::uint32_t* c, const double*) {
                 return triangle_area(xy + 2 * std::size_t{c[0]}, xy + 2 * std::size_t{c[1]},
                                      xy + 2 * std::size_t{c[2]});
             });
         }});
}

// The points, with z = 0 (Points).
void add_points(std::vector<Array>& arrays, const NodeSet& nodes) {
    arrays.push_back({Array::Section::points, "Points", "Float64", 3,
                      24 * std::uint64_t{nodes.size()}, [&nodes](File& f) {
                          Appender<double> out(f);
                          for (std::size_t v = 0; v < nodes.size(); ++v) {
                              out.push(nodes.xy[2 * v]);
                              out.push(nodes.xy[2 * v + 1]);
                              out.push(0.0);
                          }
                          out.flush();
                      }});
}

// Where each cell's corners end in the connectivity: nc, 2 nc, ...
template <class I>
void append_offsets(File& file, std::uint64_t m, std::uint32_t nc) {
    Appender<I> out(file);
    for (std::uint64_t t = 1; t <= m; ++t) out.push(static_cast<I>(t * nc));
    out.flush();
}

// The connectivity, offsets and cell types (Cells), in 32-bit integers
// where they suffice (half the bytes), else 64-bit.
void add_cells(std::vector<Array>& arrays, const MeshExport& mesh) {
    const std::uint64_t n = mesh.nodes->size(), m = mesh.triangle_count;
    const std::uint32_t nc = mesh.corners_per_triangle;
    using S = Array::Section;
    constexpr std::uint64_t int32_limit = std::numeric_limits<std::int32_t>::max();
    const bool wide_index = n > int32_limit;
    const bool wide_offset = m * nc > int32_limit;
    arrays.push_back({S::cells, "connectivity", wide_index ? "Int64" : "Int32", 1,
                      m * nc * (wide_index ? 8 : 4), [&mesh, wide_index](File& f) {
                          if (wide_index)
                              append_connectivity<std::int64_t>(f, mesh);
                          else
                              append_connectivity<std::int32_t>(f, mesh);
                      }});
    arrays.push_back({S::cells, "offsets", wide_offset ? "Int64" : "Int32", 1,
                      m * (wide_offset ? 8 : 4), [m, nc, wide_offset](File& f) {
                          if (wide_offset)
                              append_offsets<std::int64_t>(f, m, nc);
                          else
                              append_offsets<std::int32_t>(f, m, nc);
                      }});
    arrays.push_back({S::cells, "types", "UInt8", 1, m, [m, nc](File& f) {
                          // VTK_TRIANGLE, VTK_QUADRATIC_TRIANGLE
                          const std::uint8_t type = nc == 6 ? 22 : 5;
                          Appender<std::uint8_t> out(f);
                          for (std::uint64_t t = 0; t < m; ++t) out.push(type);
                          out.flush();
                      }});
}

// Every array of the file, in the head's order (sections in VTK's order).
std::vector<Array> arrays_of(const MeshExport& mesh, const WriteFormat& format) {
    std::vector<Array> arrays;
    add_point_data(arrays, *mesh.nodes, format);
    add_cell_data(arrays, mesh);
    add_points(arrays, *mesh.nodes);
    add_cells(arrays, mesh);
    return arrays;
}

void check_consistent(const std::string& path, const MeshExport& mesh) {
    const NodeSet& nodes = *mesh.nodes;
    if (nodes.xy.size() % 2 != 0 ||
        nodes.attributes.size() != nodes.size() * nodes.attribute_count ||
        (nodes.has_markers() && nodes.markers.size() != nodes.size()) ||
        (mesh.corners_per_triangle != 3 && mesh.corners_per_triangle != 6))
        throw OutputError("cannot write " + path + ": inconsistent data");
}

// The XML head: a DataArray element per array, with its offset into the
// appended section.  That section holds the arrays in the reverse of the
// head's order.  Any order is valid VTK; this one is also read correctly by
// meshio, which turns the raw data into base64 array by array, in the order
// of the data, and finds each array's element by its old offset among
// elements whose offsets it has already replaced with new ones: with the
// head in reverse order, the element looked for always comes before any
// such element that happens to hold the same number.
void put_head(File& file, const std::vector<Array>& arrays, std::size_t points, std::size_t cells) {
    auto out = std::back_inserter(file.buffer());
    fmt::format_to(out,
                   "<?xml version=\"1.0\"?>\n"
                   "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"{}\" "
                   "header_type=\"UInt64\">\n"
                   "  <UnstructuredGrid>\n"
                   "    <Piece NumberOfPoints=\"{}\" NumberOfCells=\"{}\">\n",
                   std::endian::native == std::endian::little ? "LittleEndian" : "BigEndian",
                   points, cells);
    static constexpr const char* section_tag[] = {"PointData", "CellData", "Points", "Cells"};
    std::vector<std::uint64_t> offsets(arrays.size());
    std::uint64_t end = 0;
    for (std::size_t i = arrays.size(); i-- > 0;) {
        offsets[i] = end;
        end += sizeof(std::uint64_t) + arrays[i].bytes;
    }
    for (std::size_t i = 0; i < arrays.size(); ++i) {
        const Array& a = arrays[i];
        const auto s = static_cast<std::size_t>(a.section);
        if (i == 0 || arrays[i - 1].section != a.section)
            fmt::format_to(out, "      <{}>\n", section_tag[s]);
        // Scalars without NumberOfComponents: readers then give them as
        // plain lists, not as lists of one-element rows.
        const std::string components =
            a.components == 1 ? "" : fmt::format(" NumberOfComponents=\"{}\"", a.components);
        fmt::format_to(out,
                       "        <DataArray type=\"{}\" Name=\"{}\"{} format=\"appended\" "
                       "offset=\"{}\"/>\n",
                       a.type, a.name, components, offsets[i]);
        if (i + 1 == arrays.size() || arrays[i + 1].section != a.section)
            fmt::format_to(out, "      </{}>\n", section_tag[s]);
    }
    fmt::format_to(out,
                   "    </Piece>\n"
                   "  </UnstructuredGrid>\n");
}

}  // namespace

void write_vtu(OutputTransaction& tx, const std::string& path, const MeshExport& mesh,
               const WriteFormat& format) {
    check_consistent(path, mesh);
    const std::vector<Array> arrays = arrays_of(mesh, format);
    File& file = tx.begin_file(path);
    put_head(file, arrays, mesh.nodes->size(), mesh.triangle_count);
    // The appended section: '_', then each array, last first, as its byte
    // count and its values.
    fmt::format_to(std::back_inserter(file.buffer()),
                   "  <AppendedData encoding=\"raw\">\n"
                   "_");
    for (std::size_t i = arrays.size(); i-- > 0;) {
        const std::uint64_t bytes = arrays[i].bytes;
        file.append(&bytes, sizeof bytes);
        arrays[i].append(file);
    }
    fmt::format_to(std::back_inserter(file.buffer()),
                   "\n"
                   "  </AppendedData>\n"
                   "</VTKFile>\n");
    file.finish(format.command, format.stamp, File::Closing::xml_comment);
}

}  // namespace gpdr::io
