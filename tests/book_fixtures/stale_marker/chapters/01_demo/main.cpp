// A fixture for the book tests (book/CMakeLists.txt): [goodbye] is quoted by no page.
#include <cstdio>

int main() {
    // [hello]
    std::puts("hello");
    // [/hello]
    // [goodbye]
    std::puts("goodbye");
    // [/goodbye]
}
