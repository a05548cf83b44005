// A fixture for book/tests: its page does not show tests/golden/01_demo.png.
#include <cstdio>

int main() {
    // [hello]
    std::puts("hello");
    // [/hello]
}
