// Frame state that several effects share (Filament's Blackboard): typed values, by type and, where one type has
// several (a downsampled cube per M), by name. Borrowed values are the pass graph's resources handed to a frame;
// owned state is what an effect keeps for the renderer's lifetime (textures it uploaded), made on first use.
#pragma once

#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <typeindex>
#include <utility>

namespace metalfit::glpreview {

class Blackboard {
public:
    // `value` is read by the frames drawn from now on; the caller keeps it alive while they draw.
    template <class T>
    void put(const T& value, const std::string& name = {}) {
        borrowed_[{std::type_index(typeid(T)), name}] = &value;
    }
    // The value put under T and `name`, or null.
    template <class T>
    const T* find(const std::string& name = {}) const {
        const auto it = borrowed_.find({std::type_index(typeid(T)), name});
        return it == borrowed_.end() ? nullptr : static_cast<const T*>(it->second);
    }
    // The same; std::logic_error naming `what` when nobody put it.
    template <class T>
    const T& get(const std::string& what, const std::string& name = {}) const {
        if (const T* value = find<T>(name)) return *value;
        throw std::logic_error("GpuRenderer: " + what + " was not handed to the frame");
    }
    // State of type T owned by the blackboard (default-constructed on first use).
    template <class T>
    T& state() {
        auto& slot = owned_[std::type_index(typeid(T))];
        if (!slot) slot = std::make_shared<T>();
        return *std::static_pointer_cast<T>(slot);
    }

private:
    std::map<std::pair<std::type_index, std::string>, const void*> borrowed_;
    std::map<std::type_index, std::shared_ptr<void>> owned_;
};

}  // namespace metalfit::glpreview
