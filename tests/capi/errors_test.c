/*
 * What libtriangle does with bad switches and bad input: triangulate()
 * returns non-zero, keeps the reason for gpdr_last_error(), sets the output
 * counts to 0, allocates nothing (scripts/test-asan.sh runs this under
 * LeakSanitizer) and leaves the process running.  Also what is printed on
 * standard output with and without 'Q'.  This program defines no
 * triunsuitable(), so 'u' must be refused.
 */
#include <sys/wait.h>
#include <unistd.h>

#include "capi_support.h"

/* triangulate() on `in` must fail with a message that contains `expected`,
   set the counts of `out` (and `vorout`) to 0 and leave their pointers. */
static void expect_error(const char* switches, struct triangulateio* in, int with_vorout,
                         const char* expected) {
    struct triangulateio out = capi_empty(), vor = capi_empty();
    double mine[2];
    out.pointlist = mine; /* the caller's array: must stay */
    out.numberofpoints = 7;
    out.numberoftriangles = 7;
    vor.numberofedges = 7;
    const int status = triangulate((char*)switches, in, &out, with_vorout ? &vor : NULL);
    const char* message = gpdr_last_error();
    if (status == 0 || !strstr(message, expected))
        fprintf(stderr, "switches \"%s\": status %d, message \"%s\"; expected \"%s\"\n", switches,
                status, message, expected);
    CHECK(status != 0);
    CHECK(strstr(message, expected) != NULL);
    CHECK(out.pointlist == mine);
    CHECK(out.trianglelist == NULL && out.pointmarkerlist == NULL && out.edgelist == NULL);
    CHECK(out.numberofpoints == 0 && out.numberoftriangles == 0);
    CHECK(vor.pointlist == NULL && vor.numberofedges == (with_vorout ? 0 : 7));
}

static void errors_are_returned(void) {
    struct triangulateio in = capi_square_points();
    expect_error("pwQ", &in, 0, "weighted");
    expect_error("q70Q", &in, 0, "q70");
    expect_error("vQ", &in, 0, "vorout");
    expect_error("uQ", &in, 0, "triunsuitable");

    int segments[] = {1, 2, 2, 9};
    in.segmentlist = segments;
    in.numberofsegments = 2;
    expect_error("pQ", &in, 0, "segmentlist[3] is 9");
    segments[3] = 0; /* 0 is no vertex when numbering from 1 */
    expect_error("pQ", &in, 1, "segmentlist[3] is 0");
    in.segmentlist = NULL;
    expect_error("pQ", &in, 0, "segmentlist is NULL");

    struct triangulateio nothing = capi_empty();
    nothing.numberofpoints = 3;
    expect_error("Q", &nothing, 0, "pointlist is NULL");
    nothing.numberofpoints = -1;
    expect_error("Q", &nothing, 0, "numberofpoints is -1");

    static const double line[] = {0, 0, 1, 1, 2, 2};
    struct triangulateio collinear = capi_empty();
    collinear.pointlist = (double*)line;
    collinear.numberofpoints = 3;
    expect_error("Q", &collinear, 0, "collinear");

    /* -r: a triangle with a corner out of range, and area bounds missing. */
    struct triangulateio mesh = capi_square_points();
    int triangles[] = {1, 2, 5, 2, 3, 6};
    mesh.trianglelist = triangles;
    mesh.numberoftriangles = 2;
    mesh.numberofcorners = 3;
    expect_error("rQ", &mesh, 0, "trianglelist[5] is 6");
    triangles[5] = 5;
    expect_error("raQ", &mesh, 0, "trianglearealist is NULL");

    /* A success clears the thread's last error. */
    struct triangulateio out = capi_empty();
    CHECK(triangulate("Q", &in, &out, NULL) == 0);
    CHECK(gpdr_last_error()[0] == '\0');
    capi_free_output(&out);
}

/* In library mode Triangle skips characters that are not switches, and so
   does libtriangle; h does nothing. */
static void library_switches(void) {
    struct triangulateio in = capi_square_points(), out = capi_empty();
    CHECK(triangulate("Qz{a0.02}", &in, &out, NULL) == 0);
    CHECK(out.numberoftriangles >= 50);
    CHECK(capi_valid_triangles(&out, 0));
    for (int t = 0; t < out.numberoftriangles; ++t) CHECK(capi_area2(&out, t, 0) / 2 <= 0.02);
    capi_free_output(&out);
    CHECK(triangulate("-hQ", &in, &out, NULL) == 0);
    CHECK(out.numberoftriangles == 4);
    capi_free_output(&out);
    /* L is Triangle's other name for D. */
    CHECK(triangulate("LQ", &in, &out, NULL) == 0);
    capi_free_output(&out);
}

/* Runs `switches` on the square in a child process, collecting its standard
   output in `text`; returns the child's exit status (-1 if it did not exit). */
static int run_child(char* switches, char* text, size_t size) {
    int pipe_ends[2];
    if (pipe(pipe_ends) != 0) return -1;
    fflush(stdout);
    const pid_t child = fork();
    if (child == 0) {
        dup2(pipe_ends[1], 1);
        close(pipe_ends[0]);
        struct triangulateio in = capi_square_points(), out = capi_empty();
        triangulate(switches, &in, &out, NULL);
        fflush(stdout);
        _exit(0);
    }
    close(pipe_ends[1]);
    size_t used = 0;
    ssize_t n;
    while (used + 1 < size && (n = read(pipe_ends[0], text + used, size - 1 - used)) > 0)
        used += (size_t)n;
    text[used] = '\0';
    close(pipe_ends[0]);
    int status = 0;
    if (waitpid(child, &status, 0) != child || !WIFEXITED(status)) return -1;
    return WEXITSTATUS(status);
}

static void what_is_printed(void) {
    char text[8192];
    CHECK(run_child("pw", text, sizeof text) == 0);
    CHECK(strncmp(text, "Error:  -w", 10) == 0);
    CHECK(run_child("pwQ", text, sizeof text) == 0);
    CHECK(text[0] == '\0');

    CHECK(run_child("Q", text, sizeof text) == 0);
    CHECK(text[0] == '\0');

    CHECK(run_child("e", text, sizeof text) == 0);
    CHECK(strstr(text, "Writing vertices.") != NULL);
    CHECK(strstr(text, "Writing edges.") != NULL);
    CHECK(strstr(text, "Mesh triangles: 4") != NULL);
    CHECK(strstr(text, "Mesh quality statistics:") == NULL);

    CHECK(run_child("NV", text, sizeof text) == 0);
    CHECK(strstr(text, "NOT writing vertices.") != NULL);
    CHECK(strstr(text, "Mesh quality statistics:") != NULL);
}

int main(void) {
    errors_are_returned();
    library_switches();
    what_is_printed();
    return capi_finish("capi errors");
}
