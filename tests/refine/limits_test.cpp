// Criteria beyond the global bounds (regional area bounds, the .area field,
// the user test) and the limits: -Y, -YY, -S, and the safety budget that
// stops an angle bound refinement cannot meet.

#include "refine_support.hpp"

namespace gpdr::refine::testing {

namespace {

std::size_t count_subsegments(const mesh::Mesh& m) {
    std::size_t n = 0;
    mesh::for_each_edge(m, [&](const mesh::EdgeView& e) { n += e.subsegment ? 1 : 0; });
    return n;
}

double area_of(const mesh::Mesh& m, const mesh::Triangle& t) {
    return geometry::signed_area(m.point(t.v[0]), m.point(t.v[1]), m.point(t.v[2]));
}

Point centroid(const mesh::Mesh& m, const mesh::Triangle& t) {
    Point c{0, 0};
    for (auto v : t.v) c = {c.x + m.point(v).x / 3, c.y + m.point(v).y / 3};
    return c;
}

int big_on_the_right(double* org, double* dest, double* apex, double area) {
    const double x = (org[0] + dest[0] + apex[0]) / 3;
    return x > 0.5 && area > 0.0005 ? 1 : 0;
}

}  // namespace

TEST_CASE("regional area bounds follow the regions", "[refine][criteria]") {
    triangulate::Pslg p;
    p.points = {{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0.5, 0}, {0.5, 1}};
    p.segments = {0, 4, 4, 1, 1, 2, 2, 5, 5, 3, 3, 0, 4, 5};
    p.regions = {Region{0.25, 0.5, 1.0, 0.001}, Region{0.75, 0.5, 2.0, 0.02}};
    mesh::Mesh m = cdt(p);
    RefineSettings settings;
    settings.criteria.min_angle_degrees = 20;
    settings.criteria.region_max_area = {-1.0, 0.001, 0.02};
    RefineReport report;
    refine_mesh(m, settings, report);
    examine(m, settings);
    std::size_t left = 0, right = 0;
    mesh::for_each_triangle(m, [&](mesh::TriangleId, const mesh::Triangle& t) {
        REQUIRE((t.region == 1 || t.region == 2));
        CHECK(area_of(m, t) <= settings.criteria.region_max_area[t.region]);
        (t.region == 1 ? left : right) += 1;
    });
    CHECK(left > 5 * right);
}

TEST_CASE("the .area field holds every triangle to the bound at its centroid",
          "[refine][criteria]") {
    mesh::Mesh m = point_set_mesh(random_points(50, 21));
    // The starting triangles as an .ele would list them, a small bound on
    // those left of x = 0.5 and a larger one on the others.
    std::vector<Point> points;
    for (std::uint32_t v = 0; v < m.vertex_end(); ++v) points.push_back(m.point(mesh::VertexId{v}));
    std::vector<std::uint32_t> corners;
    std::vector<double> bounds;
    mesh::for_each_triangle(m, [&](mesh::TriangleId, const mesh::Triangle& t) {
        for (auto v : t.v) corners.push_back(mesh::index(v));
        bounds.push_back(centroid(m, t).x < 0.5 ? 0.0005 : 0.01);
    });
    const geometry::AreaField field(points, corners, 3, bounds);
    RefineSettings settings;
    settings.criteria.min_angle_degrees = 20;
    settings.criteria.area_field = &field;
    RefineReport report;
    refine_mesh(m, settings, report);
    examine(m, settings);
    // Every triangle meets the bound at its centroid, and those under the
    // small bound tile about the area it was written for.
    double small_area = 0;
    std::size_t small = 0;
    mesh::for_each_triangle(m, [&](mesh::TriangleId, const mesh::Triangle& t) {
        const Point c = geometry::centroid(m.point(t.v[0]), m.point(t.v[1]), m.point(t.v[2]));
        const double bound = field.at(c).area;
        REQUIRE((bound == 0.0005 || bound == 0.01));
        CHECK(area_of(m, t) <= bound);
        if (bound == 0.0005) {
            ++small;
            small_area += area_of(m, t);
        }
    });
    double written = 0;  // the area of the starting triangles bounded by 0.0005
    for (std::size_t t = 0; t < bounds.size(); ++t)
        if (bounds[t] == 0.0005)
            written += geometry::signed_area(points[corners[3 * t]], points[corners[3 * t + 1]],
                                             points[corners[3 * t + 2]]);
    CHECK(small_area > 0.9 * written);
    CHECK(small_area < 1.1 * written);
    CHECK(static_cast<double>(small) >= written / 0.0005);
}

TEST_CASE("the user test is applied after the area checks", "[refine][criteria]") {
    mesh::Mesh m = point_set_mesh(random_points(40, 9));
    RefineSettings settings;
    settings.criteria.min_angle_degrees = 20;
    settings.criteria.user_test = &big_on_the_right;
    RefineReport report;
    refine_mesh(m, settings, report);
    examine(m, settings);
    mesh::for_each_triangle(m, [&](mesh::TriangleId, const mesh::Triangle& t) {
        double a[2] = {m.point(t.v[0]).x, m.point(t.v[0]).y},
               b[2] = {m.point(t.v[1]).x, m.point(t.v[1]).y},
               c[2] = {m.point(t.v[2]).x, m.point(t.v[2]).y};
        CHECK(big_on_the_right(a, b, c, area_of(m, t)) == 0);
    });
}

TEST_CASE("switch -Y keeps boundary subsegments whole, -YY every subsegment", "[refine][limits]") {
    SECTION("-Y on a point set") {
        mesh::Mesh m = point_set_mesh(random_points(60, 4));
        const std::size_t hull = mesh::count_hull_edges(m);
        RefineSettings settings;
        settings.criteria.min_angle_degrees = 25;
        settings.criteria.max_area = 0.005;
        settings.no_segment_splitting = 1;
        RefineReport report;
        refine_mesh(m, settings, report);
        examine(m, settings);
        CHECK(report.segment_splits == 0);
        CHECK(mesh::count_hull_edges(m) == hull);
        CHECK(report.steiner_points > 0);
        CHECK(report.left_other == 0);
    }
    SECTION("-YY on a PSLG with an interior segment") {
        triangulate::Pslg p;
        p.points = {{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0.2, 0.5}, {0.8, 0.52}};
        p.segments = {0, 1, 1, 2, 2, 3, 3, 0, 4, 5};
        mesh::Mesh m = cdt(p);
        const std::size_t subsegments = count_subsegments(m);
        RefineSettings settings;
        settings.criteria.min_angle_degrees = 20;
        settings.criteria.max_area = 0.01;
        settings.no_segment_splitting = 2;
        RefineReport report;
        refine_mesh(m, settings, report);
        examine(m, settings);
        CHECK(report.segment_splits == 0);
        CHECK(count_subsegments(m) == subsegments);
        CHECK(report.left_other == 0);
    }
}

TEST_CASE("switch -S caps the Steiner points and the report says what is left",
          "[refine][limits]") {
    mesh::Mesh m = point_set_mesh(random_points(60, 8));
    RefineSettings settings;
    settings.criteria.min_angle_degrees = 30;
    settings.criteria.max_area = 0.001;
    settings.steiner_limit = true;
    settings.max_steiner = 25;
    RefineReport report;
    refine_mesh(m, settings, report);
    examine(m, settings);
    CHECK(report.steiner_points == 25);
    CHECK(report.stopped == RefineReport::Stop::steiner_limit);
    CHECK(report.left_budget > 0);
    CHECK(report.left_other == 0);
}

TEST_CASE("an unreachable angle bound stops with a valid mesh", "[refine][limits]") {
    mesh::Mesh m = point_set_mesh(random_points(30, 2));
    RefineSettings settings;
    settings.criteria.min_angle_degrees = 45;
    settings.safety_limit = 20000;
    RefineReport report;
    refine_mesh(m, settings, report);
    const auto problems = mesh::check_mesh(m);
    INFO(joined(problems));
    CHECK(problems.empty());
    CHECK(report.stopped == RefineReport::Stop::safety_limit);
    CHECK(report.steiner_points == 20000);
    CHECK(report.safety_limit == 20000);  // the warning names the limit that stopped it
    CHECK(report.left_budget + report.left_precision > 0);
}

}  // namespace gpdr::refine::testing
