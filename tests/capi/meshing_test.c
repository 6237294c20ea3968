/*
 * triangulate() through libtriangle.so, switch by switch, as a C program
 * written for Triangle's library calls it.  Every check looks at the arrays
 * returned: counts, numbering, geometry, markers, and who allocated what.
 */
#include "capi_support.h"

/* -u: refine every triangle larger than this (a program linked with
   libtriangle provides it, as one linked with Triangle's -DEXTERNAL_TEST
   build does). */
static const double unsuitable_area = 0.02;

/* Each corner is Triangle's vertex record: x, y, then the attributes.  When
   the user test below gives the points one attribute, x + 2y, every corner
   must carry it (linear interpolation keeps it exact); corners that do not
   are counted. */
static int corners_have_attribute = 0;
static int corners_without_it = 0;

static void check_corner(const double* corner) {
    if (corners_have_attribute && fabs(corner[2] - (corner[0] + 2 * corner[1])) > 1e-12)
        ++corners_without_it;
}

int triunsuitable(double* org, double* dest, double* apex, double area) {
    check_corner(org);
    check_corner(dest);
    check_corner(apex);
    return area > unsuitable_area;
}

static void delaunay_of_points(void) {
    for (int zero = 0; zero <= 1; ++zero) {
        const int base = zero ? 0 : 1;
        struct triangulateio in = capi_square_points(), out = capi_empty();
        CHECK(triangulate(zero ? "zQ" : "Q", &in, &out, NULL) == 0);
        CHECK(out.numberofpoints == 5);
        CHECK(out.numberoftriangles == 4);
        CHECK(out.numberofcorners == 3);
        CHECK(out.numberofedges == 8);
        CHECK(out.numberofsegments == 4); /* no segments used: the hull's edges */
        CHECK(capi_valid_triangles(&out, base));
        CHECK(fabs(capi_total_area(&out, base) - 1) < 1e-12);
        CHECK(memcmp(out.pointlist, in.pointlist, 10 * sizeof(double)) == 0);
        /* The hull's corners are on the boundary (1), the centre is not (0). */
        CHECK(out.pointmarkerlist != NULL);
        for (int v = 0; v < 5 && out.pointmarkerlist; ++v) CHECK(out.pointmarkerlist[v] == (v < 4));
        /* Not asked for: not allocated. */
        CHECK(out.neighborlist == NULL && out.edgelist == NULL && out.segmentlist == NULL);
        CHECK(out.pointattributelist == NULL && out.triangleattributelist == NULL);
        capi_free_output(&out);
    }
}

/* A 10 x 10 square with a 2 x 2 square hole in the middle: segments marked 5
   outside and 7 around the hole. */
static int inside_hole(const double* p) { return p[0] > 4 && p[0] < 6 && p[1] > 4 && p[1] < 6; }

static void quality_pslg_with_hole(void) {
    struct triangulateio in = capi_frame(), out = capi_empty();
    CHECK(triangulate("pq30a0.5j2Q", &in, &out, NULL) == 0);
    CHECK(out.numberoftriangles > 200);
    CHECK(capi_valid_triangles(&out, 1));
    CHECK(fabs(capi_total_area(&out, 1) - 96) < 1e-9);
    for (int t = 0; t < out.numberoftriangles; ++t) {
        CHECK(capi_min_angle(&out, t, 1) >= 30 - 1e-9);
        CHECK(capi_area2(&out, t, 1) / 2 <= 0.5 * (1 + 1e-12));
        const int* c = out.trianglelist + 3 * t;
        double centroid[2] = {0, 0};
        for (int k = 0; k < 3; ++k)
            for (int d = 0; d < 2; ++d) centroid[d] += capi_point(&out, c[k], 1)[d] / 3;
        CHECK(!inside_hole(centroid));
    }
    /* The subsegments, with the markers of the segments they lie on. */
    CHECK(out.numberofsegments > 8 && out.segmentlist && out.segmentmarkerlist);
    for (int s = 0; s < out.numberofsegments && out.segmentlist; ++s) {
        const double* a = capi_point(&out, out.segmentlist[2 * s], 1);
        const double* b = capi_point(&out, out.segmentlist[2 * s + 1], 1);
        const int outer = a[0] == 0 || a[0] == 10 || a[1] == 0 || a[1] == 10;
        CHECK(out.segmentmarkerlist[s] == (outer ? 5 : 7));
        CHECK(a[0] == b[0] || a[1] == b[1]); /* along a side */
    }
    /* Holes and regions are handed back as the input's own arrays. */
    CHECK(out.holelist == in.holelist && out.numberofholes == 1);
    CHECK(out.regionlist == NULL && out.numberofregions == 0);
    capi_free_output(&out);
}

static void edges_neighbours_voronoi(void) {
    struct triangulateio in = capi_square_points(), out = capi_empty(), vor = capi_empty();
    CHECK(triangulate("envQ", &in, &out, &vor) == 0);
    CHECK(out.numberofedges == 8 && out.edgelist && out.edgemarkerlist && out.neighborlist);
    int boundary = 0;
    for (int e = 0; e < out.numberofedges && out.edgelist; ++e) {
        CHECK(out.edgelist[2 * e] >= 1 && out.edgelist[2 * e] <= 5);
        CHECK(out.edgelist[2 * e + 1] >= 1 && out.edgelist[2 * e + 1] <= 5);
        boundary += out.edgemarkerlist[e] == 1;
    }
    CHECK(boundary == 4);
    /* Neighbour k is across from corner k, and the relation is symmetric. */
    for (int t = 0; t < out.numberoftriangles && out.neighborlist; ++t)
        for (int k = 0; k < 3; ++k) {
            const int u = out.neighborlist[3 * t + k];
            if (u == -1) continue;
            CHECK(u >= 1 && u <= out.numberoftriangles);
            int back = 0;
            for (int j = 0; j < 3; ++j) back += out.neighborlist[3 * (u - 1) + j] == t + 1;
            CHECK(back == 1);
        }
    /* One Voronoi vertex per triangle, its circumcentre: for these four right
       triangles, the midpoint of a side of the square. */
    CHECK(vor.numberofpoints == 4 && vor.numberofedges == 8);
    CHECK(vor.pointlist && vor.edgelist && vor.normlist);
    for (int v = 0; v < vor.numberofpoints && vor.pointlist; ++v) {
        const double x = vor.pointlist[2 * v], y = vor.pointlist[2 * v + 1];
        CHECK(fabs(fabs(x - 0.5) + fabs(y - 0.5) - 0.5) < 1e-12);
        CHECK(fabs(x - 0.5) < 1e-12 || fabs(y - 0.5) < 1e-12);
    }
    CHECK(vor.pointmarkerlist == NULL && vor.edgemarkerlist == NULL);
    int rays = 0;
    for (int e = 0; e < vor.numberofedges && vor.edgelist; ++e) {
        const double dx = vor.normlist[2 * e], dy = vor.normlist[2 * e + 1];
        if (vor.edgelist[2 * e + 1] == -1) {
            ++rays;
            CHECK(dx != 0 || dy != 0);
        } else {
            CHECK(dx == 0 && dy == 0);
        }
    }
    CHECK(rays == 4);
    capi_free_output(&out);
    capi_free_output(&vor);
}

static void refine_previous_mesh(void) {
    struct triangulateio in = capi_square_points(), first = capi_empty(), out = capi_empty();
    CHECK(triangulate("Q", &in, &first, NULL) == 0);
    double areas[4] = {0.01, 0.01, 0.2, 0.2};
    first.trianglearealist = areas;
    CHECK(triangulate("raQ", &first, &out, NULL) == 0);
    CHECK(capi_valid_triangles(&out, 1));
    CHECK(fabs(capi_total_area(&out, 1) - 1) < 1e-12);
    CHECK(out.numberoftriangles > 20);
    for (int t = 0; t < out.numberoftriangles; ++t) CHECK(capi_area2(&out, t, 1) / 2 <= 0.2);
    first.trianglearealist = NULL;
    capi_free_output(&first);
    capi_free_output(&out);
}

/* The square (0,0)-(4,4) as four triangles around (2,2), the bottom one
   bounded by trianglearealist: the bound belongs to where that triangle
   lies (docs/file-formats.md, ".area"), so the triangles whose centroid is
   there meet it and the other three input triangles stay coarse. */
static void area_list_as_a_field(void) {
    static double points[] = {0, 0, 4, 0, 4, 4, 0, 4, 2, 2};
    static int corners[] = {1, 2, 5, 2, 3, 5, 3, 4, 5, 4, 1, 5};
    static double areas[] = {0.01, -1, -1, -1};
    struct triangulateio in = capi_empty(), out = capi_empty();
    in.pointlist = points;
    in.numberofpoints = 5;
    in.trianglelist = corners;
    in.numberoftriangles = 4;
    in.numberofcorners = 3;
    in.trianglearealist = areas;
    CHECK(triangulate("raQ", &in, &out, NULL) == 0);
    CHECK(capi_valid_triangles(&out, 1));
    CHECK(fabs(capi_total_area(&out, 1) - 16) < 1e-9);
    int bottom = 0;
    for (int t = 0; t < out.numberoftriangles; ++t) {
        double x = 0, y = 0;
        for (int k = 0; k < 3; ++k) {
            const int v = out.trianglelist[3 * t + k] - 1;
            x += out.pointlist[2 * v] / 3;
            y += out.pointlist[2 * v + 1] / 3;
        }
        if (y <= x && y <= 4 - x) {
            ++bottom;
            CHECK(capi_area2(&out, t, 1) / 2 <= 0.01 * (1 + 1e-12));
        }
    }
    CHECK(bottom >= 400);
    CHECK(4 * (out.numberoftriangles - bottom) <= out.numberoftriangles);
    capi_free_output(&out);
}

static void second_order(void) {
    struct triangulateio in = capi_square_points(), out = capi_empty();
    CHECK(triangulate("o2Q", &in, &out, NULL) == 0);
    CHECK(out.numberofcorners == 6 && out.numberoftriangles == 4);
    CHECK(out.numberofpoints == 5 + 8); /* a node at each edge's midpoint */
    for (int t = 0; t < out.numberoftriangles; ++t) {
        const int* c = out.trianglelist + 6 * t;
        for (int k = 0; k < 3; ++k) {
            /* Node 3 + k is the midpoint of the edge opposite corner k. */
            const double* a = capi_point(&out, c[(k + 1) % 3], 1);
            const double* b = capi_point(&out, c[(k + 2) % 3], 1);
            const double* m = capi_point(&out, c[3 + k], 1);
            CHECK(m[0] == (a[0] + b[0]) / 2 && m[1] == (a[1] + b[1]) / 2);
        }
    }
    capi_free_output(&out);
}

/* Two regions of the unit square, split at x = 0.5 by a segment. */
static void regional_attributes_and_areas(void) {
    static const double points[] = {0, 0, 0.5, 0, 1, 0, 1, 1, 0.5, 1, 0, 1};
    static int segments[] = {1, 2, 2, 3, 3, 4, 4, 5, 5, 6, 6, 1, 2, 5};
    static double regions[] = {0.25, 0.5, 1.0, 0.001, 0.75, 0.5, 2.0, -1};
    struct triangulateio in = capi_empty(), out = capi_empty();
    in.pointlist = (double*)points;
    in.numberofpoints = 6;
    in.segmentlist = segments;
    in.numberofsegments = 7;
    in.regionlist = regions;
    in.numberofregions = 2;
    CHECK(triangulate("pAaQ", &in, &out, NULL) == 0);
    CHECK(out.numberoftriangleattributes == 1 && out.triangleattributelist);
    int left = 0, right = 0;
    for (int t = 0; t < out.numberoftriangles && out.triangleattributelist; ++t) {
        const int* c = out.trianglelist + 3 * t;
        const double x = (capi_point(&out, c[0], 1)[0] + capi_point(&out, c[1], 1)[0] +
                          capi_point(&out, c[2], 1)[0]) /
                         3;
        const double attribute = out.triangleattributelist[t];
        CHECK(attribute == (x < 0.5 ? 1.0 : 2.0));
        if (x < 0.5) {
            ++left;
            CHECK(capi_area2(&out, t, 1) / 2 <= 0.001);
        } else {
            ++right;
        }
    }
    CHECK(left >= 250 && right >= 2 && right < left);
    CHECK(out.regionlist == regions && out.numberofregions == 2);
    capi_free_output(&out);
}

/* Vertex attributes are interpolated linearly at new vertices, so a linear
   function of position stays exact. */
static void vertex_attributes(void) {
    struct triangulateio in = capi_square_points(), out = capi_empty();
    double attributes[5];
    for (int v = 0; v < 5; ++v) attributes[v] = in.pointlist[2 * v] + 2 * in.pointlist[2 * v + 1];
    in.pointattributelist = attributes;
    in.numberofpointattributes = 1;
    CHECK(triangulate("qa0.01Q", &in, &out, NULL) == 0);
    CHECK(out.numberofpointattributes == 1 && out.pointattributelist);
    CHECK(out.numberofpoints > 50);
    for (int v = 0; v < out.numberofpoints && out.pointattributelist; ++v) {
        const double* p = out.pointlist + 2 * v;
        CHECK(fabs(out.pointattributelist[v] - (p[0] + 2 * p[1])) < 1e-12);
    }
    capi_free_output(&out);
}

/* Arrays the caller allocated are filled in place; switches that leave an
   output out leave its pointers alone. */
static void caller_arrays_and_omissions(void) {
    struct triangulateio in = capi_square_points(), out = capi_empty();
    double points[10];
    int triangles[12];
    out.pointlist = points;
    out.trianglelist = triangles;
    CHECK(triangulate("BQ", &in, &out, NULL) == 0);
    CHECK(out.pointlist == points && out.trianglelist == triangles);
    CHECK(memcmp(points, in.pointlist, sizeof points) == 0);
    CHECK(out.pointmarkerlist == NULL); /* B: no markers */
    CHECK(capi_valid_triangles(&out, 1));

    struct triangulateio none = capi_empty();
    CHECK(triangulate("NEQ", &in, &none, NULL) == 0);
    CHECK(none.pointlist == NULL && none.trianglelist == NULL && none.pointmarkerlist == NULL);
    CHECK(none.numberofpoints == 5 && none.numberoftriangles == 4);
    capi_free_output(&none);
}

/* A duplicate vertex stays in the output (unused) unless j. */
static void duplicates_and_jettison(void) {
    static const double points[] = {0, 0, 1, 0, 1, 1, 1, 0, 0, 1};
    struct triangulateio in = capi_empty(), kept = capi_empty(), dropped = capi_empty();
    in.pointlist = (double*)points;
    in.numberofpoints = 5;
    CHECK(triangulate("Q", &in, &kept, NULL) == 0);
    CHECK(triangulate("jQ", &in, &dropped, NULL) == 0);
    CHECK(kept.numberofpoints == 5 && kept.numberoftriangles == 2);
    CHECK(dropped.numberofpoints == 4 && dropped.numberoftriangles == 2);
    CHECK(capi_valid_triangles(&dropped, 1));
    capi_free_output(&kept);
    capi_free_output(&dropped);
}

static void convex_hull_segments(void) {
    struct triangulateio in = capi_square_points(), out = capi_empty();
    CHECK(triangulate("cQ", &in, &out, NULL) == 0);
    CHECK(out.numberofsegments == 4 && out.segmentlist && out.segmentmarkerlist);
    for (int s = 0; s < out.numberofsegments && out.segmentlist; ++s) {
        CHECK(out.segmentlist[2 * s] != 5 && out.segmentlist[2 * s + 1] != 5);
        CHECK(out.segmentmarkerlist[s] == 1);
    }
    CHECK(out.holelist == NULL && out.numberofholes == 0);
    capi_free_output(&out);
}

static void user_test(void) {
    struct triangulateio in = capi_square_points(), out = capi_empty();
    double attributes[5];
    for (int v = 0; v < 5; ++v) attributes[v] = in.pointlist[2 * v] + 2 * in.pointlist[2 * v + 1];
    in.pointattributelist = attributes;
    in.numberofpointattributes = 1;
    corners_have_attribute = 1;
    corners_without_it = 0;
    CHECK(triangulate("uQ", &in, &out, NULL) == 0);
    corners_have_attribute = 0;
    CHECK(corners_without_it == 0);
    CHECK(out.numberoftriangles >= 50);
    for (int t = 0; t < out.numberoftriangles; ++t)
        CHECK(capi_area2(&out, t, 1) / 2 <= unsuitable_area);
    capi_free_output(&out);
}

/* u through gpdr_triangulate_ex(): a callback with data of its own, called
   from two refining threads. */
static int larger_than(void* limit, double* org, double* dest, double* apex, double area) {
    (void)org;
    (void)dest;
    (void)apex;
    return area > *(const double*)limit;
}

static void unsuitable_callback(void) {
    double limit = 0.005;
    struct gpdr_triangulate_options options;
    memset(&options, 0, sizeof options);
    options.size = sizeof options;
    options.threads = 2;
    options.unsuitable = larger_than;
    options.user_data = &limit;
    struct triangulateio in = capi_square_points(), out = capi_empty();
    CHECK(gpdr_triangulate_ex("uQ", &in, &out, NULL, &options) == 0);
    CHECK(out.numberoftriangles >= 200);
    for (int t = 0; t < out.numberoftriangles; ++t) CHECK(capi_area2(&out, t, 1) / 2 <= limit);
    capi_free_output(&out);
}

/* A PSLG with a hole, two regions and attributes, meshed with pczAevn, then
   that output refined with an area bound per triangle (prazBP). */
static void pslg_then_refined_output(void) {
    /* A 10 x 10 square, a 2 x 2 hole in it, and a segment at x = 2 that
       divides it into the regions of attribute 10 and 20. */
    static const double points[] = {0, 0, 10, 0, 10, 10, 0, 10, 4, 4,
                                    6, 4, 6,  6, 4,  6,  2, 0,  2, 10};
    static double attributes[] = {0, 0, 10, 0, 10, 10, 0, 10, 4, 4, 6, 4, 6, 6, 4, 6, 2, 0, 2, 10};
    static int segments[] = {0, 8, 8, 1, 1, 2, 2, 9, 9, 3, 3, 0, 4, 5, 5, 6, 6, 7, 7, 4, 8, 9};
    static int markers[] = {2, 2, 2, 2, 2, 2, 3, 3, 3, 3, 0};
    static double hole[] = {5, 5};
    static double regions[] = {1, 1, 10, 0, 9, 9, 20, 0};
    struct triangulateio in = capi_empty(), mesh = capi_empty(), vor = capi_empty();
    in.pointlist = (double*)points;
    in.numberofpoints = 10;
    in.pointattributelist = attributes; /* x, y: linear, so interpolation keeps them exact */
    in.numberofpointattributes = 2;
    in.segmentlist = segments;
    in.segmentmarkerlist = markers;
    in.numberofsegments = 11;
    in.holelist = hole;
    in.numberofholes = 1;
    in.regionlist = regions;
    in.numberofregions = 2;
    CHECK(triangulate("pczAevnQ", &in, &mesh, &vor) == 0);
    CHECK(capi_valid_triangles(&mesh, 0));
    CHECK(fabs(capi_total_area(&mesh, 0) - 96) < 1e-9);
    CHECK(mesh.numberoftriangleattributes == 1);
    for (int t = 0; t < mesh.numberoftriangles; ++t) {
        const int* c = mesh.trianglelist + 3 * t;
        const double x =
            (mesh.pointlist[2 * c[0]] + mesh.pointlist[2 * c[1]] + mesh.pointlist[2 * c[2]]) / 3;
        CHECK(mesh.triangleattributelist[t] == (x < 2 ? 10 : 20));
    }
    CHECK(mesh.numberofedges > 0 && mesh.edgelist && mesh.neighborlist);
    CHECK(vor.numberofpoints == mesh.numberoftriangles && vor.pointattributelist);
    CHECK(mesh.numberofsegments == 11 && mesh.segmentmarkerlist);
    CHECK(mesh.holelist == hole && mesh.regionlist == regions);

    double* areas = malloc(sizeof(double) * (size_t)mesh.numberoftriangles);
    for (int t = 0; t < mesh.numberoftriangles; ++t) areas[t] = capi_area2(&mesh, t, 0) / 8;
    mesh.trianglearealist = areas;
    struct triangulateio refined = capi_empty();
    CHECK(triangulate("prazBPQ", &mesh, &refined, NULL) == 0);
    CHECK(capi_valid_triangles(&refined, 0));
    CHECK(fabs(capi_total_area(&refined, 0) - 96) < 1e-9);
    /* Every triangle's bound is one of those given, each a quarter of a
       first triangle's area: no first triangle survives, and no refined
       triangle is larger than the largest bound. */
    double largest_bound = 0;
    for (int t = 0; t < mesh.numberoftriangles; ++t)
        if (areas[t] > largest_bound) largest_bound = areas[t];
    CHECK(refined.numberoftriangles > 2 * mesh.numberoftriangles);
    for (int t = 0; t < refined.numberoftriangles; ++t)
        CHECK(capi_area2(&refined, t, 0) / 2 <= largest_bound * (1 + 1e-12));
    CHECK(refined.pointmarkerlist == NULL && refined.segmentlist == NULL); /* B, P */
    CHECK(refined.numberofsegments > mesh.numberofsegments);
    CHECK(refined.numberoftriangleattributes == 1 && refined.triangleattributelist);
    for (int v = 0; v < refined.numberofpoints; ++v) {
        CHECK(fabs(refined.pointattributelist[2 * v] - refined.pointlist[2 * v]) < 1e-9);
        CHECK(fabs(refined.pointattributelist[2 * v + 1] - refined.pointlist[2 * v + 1]) < 1e-9);
    }
    /* The input vertices come first, in input order. */
    CHECK(memcmp(refined.pointlist, points, sizeof points) == 0);
    free(areas);
    mesh.trianglearealist = NULL;
    capi_free_output(&refined);
    capi_free_output(&mesh);
    capi_free_output(&vor);
}

int main(void) {
    delaunay_of_points();
    quality_pslg_with_hole();
    edges_neighbours_voronoi();
    refine_previous_mesh();
    area_list_as_a_field();
    second_order();
    regional_attributes_and_areas();
    vertex_attributes();
    caller_arrays_and_omissions();
    duplicates_and_jettison();
    convex_hull_segments();
    user_test();
    unsuitable_callback();
    pslg_then_refined_output();
    return capi_finish("capi meshing");
}
