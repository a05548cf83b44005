#pragma once
// A fixture for the book tests (book/CMakeLists.txt): a constant with two
// definitions, a default and a value for another device.
struct Tuning {
    unsigned group = 128;
    static Tuning for_cpu() {
        Tuning t;
        t.group = 64;
        return t;
    }
};
