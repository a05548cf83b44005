// A fixture for the book tests (book/CMakeLists.txt): its page does not
// show tests/golden/01_demo.png.
#include <cstdio>

int main() {
    // [hello]
    std::puts("hello");
    // [/hello]
}
