/*
 * grading.c: a worked example of a user-supplied triunsuitable(), the
 * grading function (10) of the GPDR paper (Chernikov & Chrisochoides,
 * "Generalized Delaunay Mesh Refinement: From Scalar to Parallel", section
 * 3.1), written for poly-samples/pipe.poly: a pipe of radius 200 centred at
 * (200, 200).
 *
 * The paper's rule: a triangle is too big when its area exceeds
 *
 *     bound(x, y) = c * (sqrt((x - 200)^2 + (y - 200)^2) + 1)
 *
 * at its centroid (x, y).  The bound grows linearly with the distance from
 * the pipe's centre, so the mesh is finest at the centre and coarsens
 * towards the wall.  The paper's timing experiment uses c = 1e-4 (about 17
 * million triangles with its model); its Figure 6 shows the mesh for c = 0.3.
 *
 * BUILDING.  c is fixed at compile time (default below):
 *
 *   With gpdr, at run time (no rebuild of gpdr):
 *     cc -O2 -shared -fPIC -DGRADING_C=0.3 -o grading.so grading.c
 *     gpdr -pq20 --unsuitable ./grading.so pipe.poly      (--unsuitable implies -u)
 *
 *   With gpdr, at link time (as Triangle's -DEXTERNAL_TEST):
 *     cc -O2 -c grading.c
 *     c++ -o gpdr-graded grading.o -L<gpdr build or lib dir> -lgpdr_main -lgpdr -lfmt
 *     ./gpdr-graded -pq20u pipe.poly
 *   or configure gpdr with cmake -DGPDR_TRIUNSUITABLE=poly-samples/grading.c.
 *
 *   With Triangle 1.6, which must itself be compiled with -DEXTERNAL_TEST:
 *     cc -O2 -DLINUX -DEXTERNAL_TEST -c triangle.c
 *     cc -O2 -c grading.c
 *     cc -o triangle-graded triangle.o grading.o -lm
 *     ./triangle-graded -pq20u pipe.poly
 *
 * THE CONTRACT (the same for Triangle and gpdr):
 *   - org, dest and apex point at a corner's coordinates: [0] is x, [1] is y
 *     (then the vertex attributes, if the input has any).  The corners are in
 *     counter-clockwise order.  REAL is double in a default Triangle build,
 *     which is what this file assumes.
 *   - area is the triangle's area, positive.
 *   - Return non-zero to have the triangle refined, zero to accept it.
 *   - The function is consulted only with -u, after the angle test (-q) and
 *     the area bounds (-a) have accepted the triangle.
 *   - gpdr calls it from several threads at once: it must be thread-safe.
 *     This one is: it reads only its arguments and writes nothing shared.
 *   - It must not insist forever: a bound that no triangle can meet (zero or
 *     negative here, i.e. c <= 0) would make refinement run until memory or
 *     the Steiner point limit (-S) runs out.
 *   - The name must be visible to C: a C++ file declares it extern "C".
 */
#include <math.h>

/* The paper's constant c, in area units per unit of distance.  Override it
 * on the compiler's command line: -DGRADING_C=1e-4 for the paper's timing
 * experiment.  The default is the paper's Figure 6, a mesh of a few thousand
 * triangles that is quick to make and to look at. */
#ifndef GRADING_C
#define GRADING_C 0.3
#endif

/* The focus of the grading: the centre of poly-samples/pipe.poly. */
#define GRADING_X 200.0
#define GRADING_Y 200.0

/* Compiled as C++ the name would be mangled and neither gpdr nor Triangle
 * would find it; extern "C" keeps the C name. */
#ifdef __cplusplus
extern "C"
#endif
    int
    triunsuitable(double* org, double* dest, double* apex, double area) {
    /* The centroid: the mean of the three corners. */
    double x = (org[0] + dest[0] + apex[0]) / 3.0;
    double y = (org[1] + dest[1] + apex[1]) / 3.0;

    /* The paper's bound at the centroid; the +1 keeps it positive at the focus
     * itself, so refinement there stops too. */
    double dx = x - GRADING_X;
    double dy = y - GRADING_Y;
    double bound = GRADING_C * (sqrt(dx * dx + dy * dy) + 1.0);

    return area > bound;
}
