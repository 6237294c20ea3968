/* A C program built against an installed gpdr as a user builds one: with
   triangle.h and libtriangle found by CMake or pkg-config.  It meshes the
   unit square with quality bounds and exits 0 when the mesh looks right. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <triangle.h>

int main(void) {
    double points[] = {0, 0, 1, 0, 1, 1, 0, 1};
    struct triangulateio in, out;
    memset(&in, 0, sizeof in);
    memset(&out, 0, sizeof out);
    in.pointlist = points;
    in.numberofpoints = 4;
    const int ok = triangulate("q30a0.01Q", &in, &out, NULL) == 0 && out.numberoftriangles >= 100 &&
                   out.numberofcorners == 3;
    printf("consumer.c: %d triangles\n", out.numberoftriangles);
    trifree(out.pointlist);
    trifree(out.pointmarkerlist);
    trifree(out.trianglelist);
    return ok ? 0 : 1;
}
