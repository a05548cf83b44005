// Fixture of house.duplicates_can_fail. A third copy of 05_a's block, which no row of
// CONTRIBUTING.md allows.

int main() {
    const int copy_2 = 2;
    return copy_2;
}

int sum_of_squares(const int* values, int count) {
    int total = 0;
    for (int i = 0; i < count; ++i) {
        const int v = values[i];
        total += v * v;
    }
    if (total < 0) {
        total = -total;
    }
    const int rounded = (total + 7) / 8 * 8;
    const int halved = rounded / 2;
    return halved + count;
}
