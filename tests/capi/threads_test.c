/*
 * Eight threads calling triangulate() at once, as a program that meshes
 * several domains side by side does.  libtriangle keeps no state between or
 * across calls, so each thread's meshes must equal those of the same calls
 * made alone.  On one thread (the library's default) a call makes the same
 * mesh every time; calls with j2 refine in parallel inside the call as
 * well, and are checked for quality instead.  scripts/test-tsan.sh also runs this
 * under ThreadSanitizer.
 */
#include <pthread.h>

#include "capi_support.h"

enum { thread_count = 8, rounds = 6 };

/* Each thread's sequential switches differ in their area bound. */
static void switches_of(int thread, char* text, size_t size) {
    snprintf(text, size, "pq28a%gQ", 0.05 + 0.01 * thread);
}

static struct triangulateio reference[thread_count];
static int failures[thread_count];

static int same_mesh(const struct triangulateio* a, const struct triangulateio* b) {
    return a->numberofpoints == b->numberofpoints && a->numberoftriangles == b->numberoftriangles &&
           memcmp(a->pointlist, b->pointlist, 2 * sizeof(double) * a->numberofpoints) == 0 &&
           memcmp(a->trianglelist, b->trianglelist, 3 * sizeof(int) * a->numberoftriangles) == 0;
}

static void* work(void* argument) {
    const int thread = (int)(size_t)argument;
    char switches[64];
    switches_of(thread, switches, sizeof switches);
    for (int round = 0; round < rounds; ++round) {
        struct triangulateio in = capi_frame(), out = capi_empty();
        if (triangulate(switches, &in, &out, NULL) != 0) ++failures[thread];
        if (!same_mesh(&out, &reference[thread])) ++failures[thread];
        capi_free_output(&out);

        struct triangulateio parallel = capi_empty();
        if (triangulate("pq30a0.02j2Q", &in, &parallel, NULL) != 0) ++failures[thread];
        if (!capi_valid_triangles(&parallel, 1) || fabs(capi_total_area(&parallel, 1) - 96) > 1e-9)
            ++failures[thread];
        for (int t = 0; t < parallel.numberoftriangles; ++t)
            if (capi_min_angle(&parallel, t, 1) < 30 - 1e-9) ++failures[thread];
        capi_free_output(&parallel);
    }
    return NULL;
}

int main(void) {
    for (int t = 0; t < thread_count; ++t) {
        char switches[64];
        switches_of(t, switches, sizeof switches);
        struct triangulateio in = capi_frame();
        reference[t] = capi_empty();
        CHECK(triangulate(switches, &in, &reference[t], NULL) == 0);
        CHECK(reference[t].numberoftriangles > 1000);
    }
    pthread_t threads[thread_count];
    for (int t = 0; t < thread_count; ++t)
        CHECK(pthread_create(&threads[t], NULL, work, (void*)(size_t)t) == 0);
    for (int t = 0; t < thread_count; ++t) {
        pthread_join(threads[t], NULL);
        if (failures[t]) fprintf(stderr, "thread %d: %d failures\n", t, failures[t]);
        CHECK(failures[t] == 0);
        capi_free_output(&reference[t]);
    }
    return capi_finish("capi threads");
}
