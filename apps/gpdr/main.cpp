// Placeholder entry point while the command line is written (see issue 2).
#include <cstdio>
#include <cstring>
int main(int argc, char** argv) {
    if (argc > 1 && std::strcmp(argv[1], "-h") == 0) { std::puts("gpdr -p ..."); return 0; }
    std::fputs("gpdr: not implemented yet\n", stderr);
    return 1;
}
