// Fixture of house.duplicates_can_fail. The listed second copy of 05_a's block.

int main() {
    const int copy_1 = 1;
    return copy_1;
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
