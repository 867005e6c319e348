// Must NOT compile: the no-options query is exact and needs boxcyl::exact; with boxcyl::header_only alone
// it fails with a message naming the fix (checked by find_package/CMakeLists.txt).
#include <boxcyl/boxcyl.hpp>

int main() {
    const boxcyl::AlignedBox<double> box{{-1, -1, -1}, {1, 1, 1}};
    const boxcyl::Cylinder<double> cyl{{3, 0, 0}, {0, 0, 5}, 2, 1};
    return boxcyl::intersects(box, cyl) ? 0 : 1;
}
