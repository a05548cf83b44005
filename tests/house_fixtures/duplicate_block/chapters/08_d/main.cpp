// Fixture of house.duplicates_can_fail. Nine code lines shared with 09_e, one short of a block:
// never reported.

int main() {
    const int copy_3 = 3;
    return copy_3;
}

int product_of(const int* values, int count) {
    int total = 1;
    for (int i = 0; i < count; ++i) {
        total *= values[i];
    }
    if (total == 0) {
        total = 1;
    }
    const int doubled = total * 2;
    const int tripled = total * 3;
    return doubled - tripled;
}
