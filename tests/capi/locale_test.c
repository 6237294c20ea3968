/*
 * libtriangle under a locale whose decimal separator is a comma, as a
 * program that calls setlocale(LC_ALL, "") gets in Germany.  Triangle reads
 * the numbers in its switches with strtod(), which then stops at the '.';
 * gpdr reads them the same in every locale, and prints numbers with '.'.
 *
 *   locale_test LOCALE   (e.g. de_DE.UTF-8; LOCPATH may point to where it
 *                         was made with localedef)
 * Exits 77 (skipped) when the locale cannot be set.
 */
#include <locale.h>
#include <sys/wait.h>
#include <unistd.h>

#include "capi_support.h"

static const double square[] = {0, 0, 1, 0, 1, 1, 0, 1};

/* The standard output of triangulate("q25a0.015V"), run in a child. */
static void verbose_output(char* text, size_t size) {
    int ends[2];
    text[0] = '\0';
    if (pipe(ends) != 0) return;
    fflush(stdout);
    const pid_t child = fork();
    if (child == 0) {
        dup2(ends[1], 1);
        close(ends[0]);
        struct triangulateio in = capi_empty(), out = capi_empty();
        in.pointlist = (double*)square;
        in.numberofpoints = 4;
        triangulate("q25a0.015V", &in, &out, NULL);
        fflush(stdout);
        _exit(0);
    }
    close(ends[1]);
    size_t used = 0;
    ssize_t n;
    while (used + 1 < size && (n = read(ends[0], text + used, size - 1 - used)) > 0)
        used += (size_t)n;
    text[used] = '\0';
    close(ends[0]);
    waitpid(child, NULL, 0);
}

int main(int argc, char** argv) {
    if (argc != 2) {
        fprintf(stderr, "usage: %s LOCALE\n", argv[0]);
        return 2;
    }
    if (!setlocale(LC_ALL, argv[1])) {
        printf("locale %s is not available: skipped\n", argv[1]);
        return 77;
    }
    /* The locale is in force: the C library reads "0.5" as 0. */
    CHECK(strtod("0.5", NULL) == 0.0);
    CHECK(localeconv()->decimal_point[0] == ',');

    struct triangulateio in = capi_empty(), out = capi_empty();
    in.pointlist = (double*)square;
    in.numberofpoints = 4;
    CHECK(triangulate("q32.5a0.015Q", &in, &out, NULL) == 0);
    CHECK(out.numberoftriangles >= 67); /* at least 1 / 0.015 */
    for (int t = 0; t < out.numberoftriangles; ++t) {
        CHECK(capi_area2(&out, t, 1) / 2 <= 0.015);
        CHECK(capi_min_angle(&out, t, 1) >= 32.5 - 1e-9);
    }
    capi_free_output(&out);

    /* Statistics with fractions ("Smallest area: 0.0069...") keep the '.'. */
    char text[16384];
    verbose_output(text, sizeof text);
    CHECK(strstr(text, "Mesh quality statistics:") != NULL);
    CHECK(strstr(text, "0.") != NULL);
    for (const char* c = text; *c; ++c)
        if (*c == ',' && c > text && c[-1] >= '0' && c[-1] <= '9' && c[1] >= '0' && c[1] <= '9') {
            fprintf(stderr, "a decimal comma in: %.40s\n", c - 1);
            CHECK(0);
            break;
        }
    return capi_finish("capi locale");
}
