// triangulate()'s `tri` into a MeshInput (see input_dict.hpp).  Numpy
// converts each value once, to a C-contiguous table of the dtype gpdr keeps
// (double, or int64 for indices and markers so that no value wraps before it
// is checked); the table is then copied into the library's vectors.
#include "input_dict.hpp"

#include <cstdint>
#include <limits>
#include <set>
#include <string>
#include <string_view>

#include <fmt/format.h>

#include "errors.hpp"

namespace gpdr::python {
namespace {

template <class T>
using CArray = py::array_t<T, py::array::c_style | py::array::forcecast>;

// One value of `tri` as rows x columns numbers of type T.
template <class T>
struct Table {
    CArray<T> array;
    std::size_t rows = 0, columns = 0;

    const T* begin() const { return array.data(); }
    const T* end() const { return array.data() + rows * columns; }
};

template <class T>
Table<T> table(py::handle value, const std::string& key) {
    Table<T> t;
    try {
        t.array = CArray<T>(py::reinterpret_borrow<py::object>(value));
    } catch (py::error_already_set& e) {
        raise_error(fmt::format("tri['{}'] is not an array of numbers: {}", key,
                                std::string(py::str(e.value()))));
    }
    switch (t.array.ndim()) {
        case 1:  // a column, as the triangle package reads it
            t.rows = static_cast<std::size_t>(t.array.shape(0));
            t.columns = 1;
            break;
        case 2:
            t.rows = static_cast<std::size_t>(t.array.shape(0));
            t.columns = static_cast<std::size_t>(t.array.shape(1));
            break;
        default:
            raise_error(fmt::format("tri['{}'] has {} dimensions, not 2", key, t.array.ndim()));
    }
    return t;
}

template <class T>
void expect_columns(const Table<T>& t, const std::string& key, std::size_t columns) {
    if (t.rows > 0 && t.columns != columns)
        raise_error(fmt::format("tri['{}'] has {} column{}, not {}", key, t.columns,
                                t.columns == 1 ? "" : "s", columns));
}

template <class T>
void expect_rows(const Table<T>& t, const std::string& key, std::size_t rows,
                 std::string_view counted_by) {
    if (t.rows != rows)
        raise_error(fmt::format("tri['{}'] has {} rows, but tri['{}'] has {}", key, t.rows,
                                counted_by, rows));
}

// Vertex indices, each naming one of `vertex_count` vertices; messages name
// the entry as the library does ("segment 3 refers to vertex -1, ...").
std::vector<std::uint32_t> indices(const Table<std::int64_t>& t, std::size_t vertex_count,
                                   std::string_view entry) {
    std::vector<std::uint32_t> out;
    out.reserve(t.rows * t.columns);
    for (const std::int64_t v : t) {
        if (v < 0 || static_cast<std::uint64_t>(v) >= vertex_count)
            raise_error(fmt::format("{} {} refers to vertex {}, but the vertices are 0 to {}",
                                    entry, out.size() / t.columns, v,
                                    std::int64_t(vertex_count) - 1));
        out.push_back(static_cast<std::uint32_t>(v));
    }
    return out;
}

std::vector<int> markers(const Table<std::int64_t>& t, const std::string& key) {
    std::vector<int> out;
    out.reserve(t.rows);
    for (const std::int64_t v : t) {
        if (v < std::numeric_limits<int>::min() || v > std::numeric_limits<int>::max())
            raise_error(fmt::format("tri['{}'][{}] is {}, outside the range of a 32-bit int", key,
                                    out.size(), v));
        out.push_back(static_cast<int>(v));
    }
    return out;
}

std::vector<double> reals(const Table<double>& t) { return {t.begin(), t.end()}; }

// Keys read, and keys the triangle package's results and loaders hold that
// Triangle never reads.
const std::set<std::string, std::less<>> read_keys = {
    "vertices",         "vertex_attributes", "vertex_markers",
    "segments",         "segment_markers",   "holes",
    "regions",          "triangles",         "triangle_attributes",
    "triangle_max_area"};
const std::set<std::string, std::less<>> ignored_keys = {
    "neighbors", "edges", "edge_markers", "triangle_neighbors", "ray_origins", "ray_directions"};

// The values of `tri` by key, after checking that every key is known.
py::dict known_values(py::handle tri) {
    py::dict values;
    try {
        values = py::dict(py::reinterpret_borrow<py::object>(tri));
    } catch (py::error_already_set&) {
        throw py::type_error("tri must be a dictionary of arrays, such as {'vertices': points}");
    }
    for (const auto& [key, value] : values) {
        if (!py::isinstance<py::str>(key))
            raise_error(
                fmt::format("tri has a key that is not a string: {}", std::string(py::repr(key))));
        const std::string name = py::str(key);
        if (!read_keys.contains(name) && !ignored_keys.contains(name))
            raise_error(
                fmt::format("tri has an unknown key '{}' (gpdr reads vertices, vertex_attributes, "
                            "vertex_markers, segments, segment_markers, holes, regions, triangles, "
                            "triangle_attributes and triangle_max_area)",
                            name));
    }
    return values;
}

}  // namespace

ConvertedInput read_input(py::handle tri) {
    const py::dict values = known_values(tri);
    const auto has = [&values](const char* key) { return values.contains(key); };
    ConvertedInput in;
    MeshInput& m = in.mesh;
    m.name = input_name;

    std::size_t vertex_count = 0;
    if (has("vertices")) {
        const auto t = table<double>(values["vertices"], "vertices");
        expect_columns(t, "vertices", 2);
        m.nodes.xy = reals(t);
        vertex_count = t.rows;
    }
    if (has("vertex_attributes")) {
        const auto t = table<double>(values["vertex_attributes"], "vertex_attributes");
        expect_rows(t, "vertex_attributes", vertex_count, "vertices");
        m.nodes.attribute_count = static_cast<std::uint32_t>(t.columns);
        m.nodes.attributes = reals(t);
    }
    if (has("vertex_markers")) {
        const auto t = table<std::int64_t>(values["vertex_markers"], "vertex_markers");
        expect_columns(t, "vertex_markers", 1);
        expect_rows(t, "vertex_markers", vertex_count, "vertices");
        m.nodes.markers = markers(t, "vertex_markers");
    }

    std::size_t segment_count = 0;
    if (has("segments")) {
        const auto t = table<std::int64_t>(values["segments"], "segments");
        expect_columns(t, "segments", 2);
        m.segments.endpoints = indices(t, vertex_count, "segment");
        segment_count = t.rows;
    }
    if (has("segment_markers")) {
        const auto t = table<std::int64_t>(values["segment_markers"], "segment_markers");
        expect_columns(t, "segment_markers", 1);
        expect_rows(t, "segment_markers", segment_count, "segments");
        m.segments.markers = markers(t, "segment_markers");
    }
    if (has("holes")) {
        const auto t = table<double>(values["holes"], "holes");
        expect_columns(t, "holes", 2);
        m.holes = reals(t);
        in.holes = t.array.attr("copy")();
    }
    if (has("regions")) {
        const auto t = table<double>(values["regions"], "regions");
        expect_columns(t, "regions", 4);
        for (const double* r = t.begin(); r != t.end(); r += 4)
            m.regions.push_back(Region{r[0], r[1], r[2], r[3]});
        in.regions = t.array.attr("copy")();
    }

    std::size_t triangle_count = 0;
    if (has("triangles")) {
        const auto t = table<std::int64_t>(values["triangles"], "triangles");
        if (t.rows > 0 && t.columns < 3)
            raise_error(fmt::format("tri['triangles'] has {} columns, not 3 (or 6)", t.columns));
        m.triangles.corners_per_triangle = static_cast<std::uint32_t>(t.rows > 0 ? t.columns : 3);
        m.triangles.corners = indices(t, vertex_count, "triangle");
        triangle_count = t.rows;
    }
    if (has("triangle_attributes")) {
        const auto t = table<double>(values["triangle_attributes"], "triangle_attributes");
        expect_rows(t, "triangle_attributes", triangle_count, "triangles");
        m.triangles.attribute_count = static_cast<std::uint32_t>(t.columns);
        m.triangles.attributes = reals(t);
    }
    if (has("triangle_max_area")) {
        const auto t = table<double>(values["triangle_max_area"], "triangle_max_area");
        expect_columns(t, "triangle_max_area", 1);
        expect_rows(t, "triangle_max_area", triangle_count, "triangles");
        m.areas = reals(t);
    }
    return in;
}

}  // namespace gpdr::python
