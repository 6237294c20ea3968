/*
 * triangle.h -- the C interface of gpdr's libtriangle.
 *
 * libtriangle stands in for Triangle 1.6 built as a library (-DTRILIBRARY):
 * struct triangulateio has the same 23 fields, in the same order and of the
 * same types, and triangulate() and trifree() take the same arguments, so a
 * program or a binding (a Python extension, say) written against Triangle's
 * header compiles, links and runs unchanged against libtriangle.
 *
 * docs/c-api.md gives the contract of every field: which ones triangulate()
 * reads, which ones it writes, and who allocates and frees each array.
 */
#ifndef GPDR_TRIANGLE_H
#define GPDR_TRIANGLE_H

#include <stddef.h>

/* Triangle's header leaves REAL and VOID to the program that includes it.
   Here they default to double and void; a program may still define them
   first, but REAL must be double: gpdr computes in double precision only. */
#ifndef REAL
#define REAL double
#endif
#ifndef VOID
#define VOID void
#endif
typedef char gpdr_triangle_h_needs_REAL_to_be_double[sizeof(REAL) == sizeof(double) ? 1 : -1];

#if defined(__GNUC__)
#define GPDR_TRIANGLE_EXPORT __attribute__((visibility("default")))
#else
#define GPDR_TRIANGLE_EXPORT
#endif

#ifdef __cplusplus
extern "C" {
#endif

/*
 * One mesh: the input of triangulate(), or its output.  Indices count from
 * 1, or from 0 when the switches contain 'z'.  The comments say what
 * triangulate() reads from `in` and writes to `out` (and `vorout`), and
 * under which switches; each array's size is in docs/c-api.md.
 */
struct triangulateio {
    double* pointlist;           /* in; out unless N: x, y of each vertex */
    double* pointattributelist;  /* in; out unless N: numberofpointattributes each */
    int* pointmarkerlist;        /* in (NULL: all 0); out unless N or B: one each */
    int numberofpoints;          /* in; out */
    int numberofpointattributes; /* in; out */

    int* trianglelist;              /* in with r; out unless E: numberofcorners each */
    double* triangleattributelist;  /* in with r; out unless E */
    double* trianglearealist;       /* in with r and bare a: one area bound each */
    int* neighborlist;              /* out with n: 3 each, -1 where there is none */
    int numberoftriangles;          /* in with r; out */
    int numberofcorners;            /* in with r; out: 3, or 6 with o2 */
    int numberoftriangleattributes; /* in with r; out */

    int* segmentlist;       /* in with p; out with p or c, unless P: 2 each */
    int* segmentmarkerlist; /* in with p (NULL: all 0); out as segmentlist, unless B */
    int numberofsegments;   /* in with p; out */

    double* holelist;  /* in with p: a point in each hole; out: in's pointer */
    int numberofholes; /* in with p; out */

    double* regionlist;  /* in with p: x, y, attribute, area bound each; out: in's pointer */
    int numberofregions; /* in with p; out */

    int* edgelist;       /* out with e: 2 each; vorout with v: the second is -1 for a ray */
    int* edgemarkerlist; /* out with e, unless B; vorout: NULL */
    double* normlist;    /* vorout with v: each ray's direction, 0 0 for a finite edge */
    int numberofedges;   /* out; vorout */
};

/*
 * Meshes `in` as the switch letters say (those of the gpdr program, without
 * a dash and without file names; see docs/c-api.md for library mode) and
 * fills `out` and, with 'v', `vorout`.  An output array whose pointer is NULL
 * is allocated with malloc() (free it with trifree()); one that is not NULL
 * is the caller's, written in place, and must be large enough.  Unless the
 * switches contain 'Q', what the run did is printed on standard output.
 *
 * Returns 0 on success.  On failure it returns non-zero, prints the reason
 * (unless 'Q'), keeps it for gpdr_last_error(), sets the output counts to 0
 * and leaves every pointer of `out` and `vorout` as it was: nothing it
 * allocated survives.  It never ends the process.  Several threads may call
 * it at once on different structures.
 */
GPDR_TRIANGLE_EXPORT int triangulate(char* switches, struct triangulateio* in,
                                     struct triangulateio* out, struct triangulateio* vorout);

/* Frees an array that triangulate() allocated (free() would do too). */
GPDR_TRIANGLE_EXPORT void trifree(VOID* memory);

/* gpdr's own additions. */

/* Why the calling thread's last triangulate() or gpdr_triangulate_ex()
   failed; "" when it succeeded or there was none.  Valid until the thread's
   next call. */
GPDR_TRIANGLE_EXPORT const char* gpdr_last_error(void);

/* A test that asks for a triangle to be refined (non-zero) or not (0), with
   data of the caller's: Triangle's triunsuitable() with a context pointer. */
typedef int (*gpdr_unsuitable_function)(void* user_data, double* org, double* dest, double* apex,
                                        double area);

/* What gpdr_triangulate_ex() takes besides the switches.  Set `size` to
   sizeof(struct gpdr_triangulate_options) and every other field to zero,
   then what you need: later versions may add fields at the end. */
struct gpdr_triangulate_options {
    size_t size;
    /* Threads that refine: 0 as the switches say (jN; one without it). */
    unsigned threads;
    /* With 'u', called instead of triunsuitable(): from several threads at
       once when `threads` (or jN) is above 1. */
    gpdr_unsuitable_function unsuitable;
    void* user_data;
};

/* triangulate() with options; `options` may be NULL. */
GPDR_TRIANGLE_EXPORT int gpdr_triangulate_ex(const char* switches, struct triangulateio* in,
                                             struct triangulateio* out,
                                             struct triangulateio* vorout,
                                             const struct gpdr_triangulate_options* options);

#ifdef __cplusplus
}
#endif

#endif /* GPDR_TRIANGLE_H */
