// An allocator adaptor whose value-less construct() default-initialises instead of
// value-initialising: vector<T, DefaultInitAllocator<T>>::resize(n) then leaves trivially
// constructible elements (glm vectors, index arrays) unwritten instead of zero-filling them.
// Used for buffers that are about to be overwritten in full (the volume builder's output), where
// the zero-fill is a serial pass over every byte that would be written again right after.
#pragma once

#include <memory>
#include <new>
#include <utility>

namespace shadowvol {

template <class T, class Base = std::allocator<T>>
class DefaultInitAllocator : public Base {
  using Traits = std::allocator_traits<Base>;

 public:
  template <class U>
  struct rebind {
    using other = DefaultInitAllocator<U, typename Traits::template rebind_alloc<U>>;
  };

  using Base::Base;
  DefaultInitAllocator() = default;
  template <class U, class B>
  DefaultInitAllocator(const DefaultInitAllocator<U, B>& other) noexcept : Base(static_cast<const B&>(other)) {}

  template <class U>
  void construct(U* p) noexcept(std::is_nothrow_default_constructible_v<U>) {
    ::new (static_cast<void*>(p)) U;
  }
  template <class U, class... Args>
  void construct(U* p, Args&&... args) {
    Traits::construct(static_cast<Base&>(*this), p, std::forward<Args>(args)...);
  }
};

}  // namespace shadowvol
