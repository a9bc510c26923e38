// SPDX-License-Identifier: Apache-2.0
// Prints where the first counted allocations came from (alloc_counter.h), for a failing
// no-allocation test: the return address and, when the dynamic linker knows it, the symbol
// and the object file. (Code of the library's hidden functions shows the object and the
// offset in it: `addr2line -f -C -e OBJECT OFFSET` names the function.)
#pragma once

#include <dlfcn.h>

#include <cstdio>

#include "alloc_counter.h"

inline void print_first_callers(unsigned long allocations) {
    for (unsigned long i = 0; i < allocations && i < 4; ++i) {
        void* caller = alloc_counter_caller(i);
        Dl_info info;
        if (caller != nullptr && dladdr(caller, &info) != 0 && info.dli_sname != nullptr)
            std::printf("      %p %s (%s)\n", caller, info.dli_sname, info.dli_fname);
        else if (caller != nullptr && dladdr(caller, &info) != 0)  // the offset is for addr2line -e
            std::printf("      %p (%s+0x%lx)\n", caller, info.dli_fname,
                        static_cast<unsigned long>(static_cast<char*>(caller) - static_cast<char*>(info.dli_fbase)));
        else
            std::printf("      %p (?)\n", caller);
    }
}
