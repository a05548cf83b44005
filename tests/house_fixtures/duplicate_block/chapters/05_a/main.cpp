// Fixture of house.duplicates_can_fail. The block below (10 code lines: a lone brace is not one)
// stands here, in 06_b (a pair CONTRIBUTING.md lists) and in 07_c (a third copy it does not).

int main() {
    const int copy_0 = 0;
    return copy_0;
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
