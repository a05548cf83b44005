// Fixture of house.duplicates_can_fail. The other copy of 08_d's nine lines.

int main() {
    const int copy_4 = 4;
    return copy_4;
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
