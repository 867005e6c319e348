#include <boxcyl/boxcyl.hpp>
#include <cmath>
#include <iostream>

int main() {
    boxcyl::AlignedBox<double> box{{-1, -1, -1}, {1, 1, 1}};   // min, max
    boxcyl::Cylinder<double> cyl{{3, 0, 0}, {0, 0, 5}, 2, 1};  // center, axis (any length), radius, height
    bool touching = boxcyl::intersects(box, cyl);              // true: the side touches the face x = 1
    cyl.center[0] = std::nextafter(3.0, 4.0);                  // the next double after 3
    bool apart = boxcyl::intersects(box, cyl);                 // false: the cylinder misses by one ulp
    std::cout << std::boolalpha << touching << ' ' << apart << '\n';
}
