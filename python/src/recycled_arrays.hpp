// Output arrays whose memory a Renderer recycles. A frame's arrays are fresh numpy arrays that
// own their memory as far as the caller can tell, but when the last of them (and of their views)
// is freed, the block returns to its Renderer's pool for a later frame instead of to the system.
// A render loop therefore writes into memory that is already mapped: a new 640x480 RGBA + depth
// pair costs 600 page faults and zeroed pages, a tenth of a bunny frame.
#pragma once
#include <pybind11/numpy.h>

#include <cstddef>
#include <memory>
#include <mutex>
#include <vector>

namespace zraster::python {

namespace py = pybind11;

class ArrayPool : public std::enable_shared_from_this<ArrayPool> {
  public:
    // An uninitialized C-order array of `shape`, from a recycled block when one of its size is
    // free. Called with the GIL held.
    template <class T>
    py::array_t<T> array(const std::vector<py::ssize_t>& shape) {
        std::size_t count = 1;
        for (const py::ssize_t side : shape) count *= std::size_t(side);
        const Owned owned = block(count * sizeof(T));
        return py::array_t<T>(shape, static_cast<T*>(owned.data), owned.owner);
    }

    // Blocks kept free at most: two frames of every output.
    static constexpr std::size_t kMaxFreeBlocks = 16;

  private:
    struct Block;
    struct Owned {
        py::capsule owner;
        void* data;
    };
    // A block of `bytes` and the capsule owning it, whose destructor gives the block back to the
    // pool while the pool lives (and frees it otherwise).
    Owned block(std::size_t bytes);
    void give_back(Block* block);

    std::mutex mutex_;  // capsules may be freed on any Python thread
    std::vector<Block*> free_;

  public:
    ArrayPool() { free_.reserve(kMaxFreeBlocks); }  // giving a block back never allocates
    ~ArrayPool();
};

}  // namespace zraster::python
