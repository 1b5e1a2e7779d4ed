// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: the open and closed sets of the lattice searches (A* and Theta*). */
#ifndef MHPLAN_LATTICE_OPEN_LIST_H
#define MHPLAN_LATTICE_OPEN_LIST_H

#include "ompl_planners/lattice/Lattice.h"

#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

namespace mhplan
{
    /** \brief Open and closed sets of a best-first search over a Lattice's nodes (plus virtual ones): a
       binary min-heap on f with ties broken towards larger g, and one flat array that says for each node
       whether it is unseen, closed, or where it sits in the heap (decrease-key in O(log n)). No allocation
       per node; reset() costs one pass over the array. */
    class LatticeOpenList
    {
      public:
        static constexpr std::uint32_t kUnseen = 0xFFFFFFFFu;
        static constexpr std::uint32_t kClosed = 0xFFFFFFFEu;

        /** \brief One heap entry. */
        struct Item
        {
            double f;
            double g;
            LatticeNode node;
        };

        /** \brief Make every one of \e nodes nodes unseen and the heap empty. */
        void reset(std::size_t nodes)
        {
            where_.assign(nodes, kUnseen);
            heap_.clear();
        }
        bool empty() const { return heap_.empty(); }
        std::size_t openCount() const { return heap_.size(); }
        /** \brief kUnseen, kClosed, or the node's heap position. */
        std::uint32_t where(LatticeNode n) const { return where_[n]; }
        bool unseen(LatticeNode n) const { return where_[n] == kUnseen; }
        bool closed(LatticeNode n) const { return where_[n] == kClosed; }
        /** \brief Mark a node closed without it ever being open (the virtual start). */
        void close(LatticeNode n) { where_[n] = kClosed; }

        /** \brief Insert an unseen node, or lower the key of an open one (the caller checked that \e g
            improves). */
        void push(LatticeNode n, double f, double g)
        {
            std::uint32_t pos = where_[n];
            if (pos == kUnseen)
            {
                pos = static_cast<std::uint32_t>(heap_.size());
                heap_.push_back({f, g, n});
            }
            siftUp(pos, {f, g, n});
        }

        /** \brief Remove and return the best item; its node becomes closed. */
        Item pop()
        {
            const Item top = heap_.front();
            where_[top.node] = kClosed;
            const Item last = heap_.back();
            heap_.pop_back();
            if (!heap_.empty())
                siftDown(0, last);
            return top;
        }

        /** \brief Bytes held per node by the flat array. */
        static constexpr std::size_t bytesPerNode() { return sizeof(std::uint32_t); }
        /** \brief Bytes per heap entry. */
        static constexpr std::size_t bytesPerOpenNode() { return sizeof(Item); }

      private:
        static bool before(const Item &a, const Item &b) { return a.f < b.f || (a.f == b.f && a.g > b.g); }

        void siftUp(std::uint32_t pos, const Item item)
        {
            while (pos > 0)
            {
                const std::uint32_t parent = (pos - 1) >> 1;
                if (!before(item, heap_[parent]))
                    break;
                heap_[pos] = heap_[parent];
                where_[heap_[pos].node] = pos;
                pos = parent;
            }
            heap_[pos] = item;
            where_[item.node] = pos;
        }

        void siftDown(std::uint32_t pos, const Item item)
        {
            const auto n = static_cast<std::uint32_t>(heap_.size());
            for (;;)
            {
                std::uint32_t child = 2 * pos + 1;
                if (child >= n)
                    break;
                if (child + 1 < n && before(heap_[child + 1], heap_[child]))
                    ++child;
                if (!before(heap_[child], item))
                    break;
                heap_[pos] = heap_[child];
                where_[heap_[pos].node] = pos;
                pos = child;
            }
            heap_[pos] = item;
            where_[item.node] = pos;
        }

        std::vector<Item> heap_;
        std::vector<std::uint32_t> where_;
    };
} // namespace mhplan

#endif
