/*
 * What the C interface tests share: a tiny check macro that counts
 * failures, zeroed structures, freeing what triangulate() allocated, and
 * measures of the mesh it returned.  Plain C, as a user of triangle.h writes.
 */
#ifndef GPDR_TESTS_CAPI_SUPPORT_H
#define GPDR_TESTS_CAPI_SUPPORT_H

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <triangle.h>

static int capi_failures = 0;

#define CHECK(condition)                                                                  \
    do {                                                                                  \
        if (!(condition)) {                                                               \
            fprintf(stderr, "%s:%d: check failed: %s\n", __FILE__, __LINE__, #condition); \
            ++capi_failures;                                                              \
        }                                                                                 \
    } while (0)

/* Ends a test program: 0 when every check passed. */
static inline int capi_finish(const char* name) {
    if (capi_failures) {
        fprintf(stderr, "%s: %d check(s) failed\n", name, capi_failures);
        return 1;
    }
    printf("%s: all checks passed\n", name);
    return 0;
}

static inline struct triangulateio capi_empty(void) {
    struct triangulateio io;
    memset(&io, 0, sizeof io);
    return io;
}

/* The unit square's corners and its centre (a point set). */
static inline struct triangulateio capi_square_points(void) {
    static const double square[] = {0, 0, 1, 0, 1, 1, 0, 1, 0.5, 0.5};
    struct triangulateio in = capi_empty();
    in.pointlist = (double*)square;
    in.numberofpoints = 5;
    return in;
}

/* A 10 x 10 square with a 2 x 2 square hole in the middle, numbered from 1:
   outer segments marked 5, the hole's 7. */
static inline struct triangulateio capi_frame(void) {
    static const double points[] = {0, 0, 10, 0, 10, 10, 0, 10, 4, 4, 6, 4, 6, 6, 4, 6};
    static int segments[] = {1, 2, 2, 3, 3, 4, 4, 1, 5, 6, 6, 7, 7, 8, 8, 5};
    static int markers[] = {5, 5, 5, 5, 7, 7, 7, 7};
    static double hole[] = {5, 5};
    struct triangulateio in = capi_empty();
    in.pointlist = (double*)points;
    in.numberofpoints = 8;
    in.segmentlist = segments;
    in.segmentmarkerlist = markers;
    in.numberofsegments = 8;
    in.holelist = hole;
    in.numberofholes = 1;
    return in;
}

/* Frees every array of an output structure (not holelist and regionlist,
   which are the input's). */
static inline void capi_free_output(struct triangulateio* io) {
    trifree(io->pointlist);
    trifree(io->pointattributelist);
    trifree(io->pointmarkerlist);
    trifree(io->trianglelist);
    trifree(io->triangleattributelist);
    trifree(io->neighborlist);
    trifree(io->segmentlist);
    trifree(io->segmentmarkerlist);
    trifree(io->edgelist);
    trifree(io->edgemarkerlist);
    trifree(io->normlist);
    *io = capi_empty();
}

static inline const double* capi_point(const struct triangulateio* io, int index, int base) {
    return io->pointlist + 2 * (index - base);
}

/* Twice the signed area of triangle t (its first three corners). */
static inline double capi_area2(const struct triangulateio* io, int t, int base) {
    const int* c = io->trianglelist + t * io->numberofcorners;
    const double *a = capi_point(io, c[0], base), *b = capi_point(io, c[1], base),
                 *d = capi_point(io, c[2], base);
    return (b[0] - a[0]) * (d[1] - a[1]) - (b[1] - a[1]) * (d[0] - a[0]);
}

static inline double capi_total_area(const struct triangulateio* io, int base) {
    double sum = 0;
    for (int t = 0; t < io->numberoftriangles; ++t) sum += capi_area2(io, t, base) / 2;
    return sum;
}

/* The smallest angle of triangle t, in degrees. */
static inline double capi_min_angle(const struct triangulateio* io, int t, int base) {
    const int* c = io->trianglelist + t * io->numberofcorners;
    double smallest = 180;
    for (int k = 0; k < 3; ++k) {
        const double *p = capi_point(io, c[k], base), *q = capi_point(io, c[(k + 1) % 3], base),
                     *r = capi_point(io, c[(k + 2) % 3], base);
        const double ux = q[0] - p[0], uy = q[1] - p[1], vx = r[0] - p[0], vy = r[1] - p[1];
        const double angle =
            atan2(fabs(ux * vy - uy * vx), ux * vx + uy * vy) * 180 / 3.14159265358979323846;
        if (angle < smallest) smallest = angle;
    }
    return smallest;
}

/* Every corner index in range and every triangle counter-clockwise. */
static inline int capi_valid_triangles(const struct triangulateio* io, int base) {
    for (int i = 0; i < io->numberoftriangles * io->numberofcorners; ++i)
        if (io->trianglelist[i] < base || io->trianglelist[i] >= base + io->numberofpoints)
            return 0;
    for (int t = 0; t < io->numberoftriangles; ++t)
        if (capi_area2(io, t, base) <= 0) return 0;
    return 1;
}

#endif /* GPDR_TESTS_CAPI_SUPPORT_H */
