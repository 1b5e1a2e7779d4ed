// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: the pagmo algorithm object behind PagmoAlgorithmHandle (private to ompl_planners/pagmo; not
   installed). */
#ifndef MHPLAN_PAGMO_HANDLE_H
#define MHPLAN_PAGMO_HANDLE_H

#include <pagmo/algorithm.hpp>

#include <utility>

namespace mhplan
{
    /** \brief A pagmo algorithm (type-erased); it keeps its adapted state (\c memory) between evolve()
        calls. */
    class PagmoAlgorithmHandle
    {
      public:
        explicit PagmoAlgorithmHandle(pagmo::algorithm a) : algorithm(std::move(a)) {}
        pagmo::algorithm algorithm;
    };
} // namespace mhplan

#endif
