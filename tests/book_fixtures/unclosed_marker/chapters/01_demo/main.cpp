// A fixture for the book tests (book/CMakeLists.txt): [goodbye] is opened and never closed.
#include <cstdio>

int main() {
    // [hello]
    std::puts("hello");
    // [/hello]
    // [goodbye]
    std::puts("goodbye");
}
