// See recycled_arrays.hpp.
#include "recycled_arrays.hpp"

#include <algorithm>
#include <new>

namespace zraster::python {

// 64-byte aligned, as the renderer's own targets: rows start on a cache line.
struct ArrayPool::Block {
    static constexpr std::align_val_t kAlignment{64};
    std::weak_ptr<ArrayPool> pool;
    std::size_t bytes = 0;
    void* data = nullptr;

    explicit Block(std::size_t size) : bytes(size), data(::operator new(size, kAlignment)) {}
    ~Block() { ::operator delete(data, kAlignment); }
    Block(const Block&) = delete;
    Block& operator=(const Block&) = delete;
};

ArrayPool::Owned ArrayPool::block(std::size_t bytes) {
    bytes = std::max<std::size_t>(bytes, 1);
    Block* block = nullptr;
    {
        const std::lock_guard<std::mutex> lock(mutex_);
        const auto found = std::find_if(free_.begin(), free_.end(),
                                        [&](const Block* b) { return b->bytes == bytes; });
        if (found != free_.end()) {
            block = *found;
            free_.erase(found);
        }
    }
    if (block == nullptr) {
        block = new Block(bytes);
        block->pool = weak_from_this();
    }
    const PyCapsule_Destructor give_back_or_free = [](PyObject* capsule) {
        auto* b = static_cast<Block*>(PyCapsule_GetPointer(capsule, nullptr));
        const std::shared_ptr<ArrayPool> pool = b->pool.lock();
        if (!pool) {
            delete b;
            return;
        }
        try {
            pool->give_back(b);
        } catch (...) {  // no memory for the free list: the block goes back to the system
            delete b;
        }
    };
    try {
        return {py::capsule(block, nullptr, give_back_or_free), block->data};
    } catch (...) {
        delete block;
        throw;
    }
}

void ArrayPool::give_back(Block* block) {
    const std::lock_guard<std::mutex> lock(mutex_);
    if (free_.size() == kMaxFreeBlocks) {
        delete free_.front();  // the oldest: a size the renderer no longer asks for, likely
        free_.erase(free_.begin());
    }
    free_.push_back(block);
}

ArrayPool::~ArrayPool() {
    for (Block* b : free_) delete b;
}

}  // namespace zraster::python
