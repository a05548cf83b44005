// A fixture for book/tests: [goodbye] is opened and never closed.
#include <cstdio>

int main() {
    // [hello]
    std::puts("hello");
    // [/hello]
    // [goodbye]
    std::puts("goodbye");
}
