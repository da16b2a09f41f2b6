#!/usr/bin/env python3
"""A `slangc` stand-in: compiles with the Slang compiler library bundled in the slangpy wheel.

Usage: slangc.py FILE -target spirv -entry main -stage compute -o OUT
(the arguments are Slang's command line; `-o` is written by this script). Exits non-zero and prints
Slang's diagnostics when compilation fails. Used by tests/targets.rs to check naga's HLSL output.
"""
import ctypes
import glob
import os
import sys

import slangpy

lib = ctypes.CDLL(glob.glob(os.path.join(os.path.dirname(slangpy.__file__), "libslang-compiler.so*"))[0])
V = ctypes.c_void_p
lib.spCreateSession.restype = V
lib.spCreateSession.argtypes = [ctypes.c_char_p]
lib.spCreateCompileRequest.restype = V
lib.spCreateCompileRequest.argtypes = [V]
lib.spProcessCommandLineArguments.argtypes = [V, ctypes.POINTER(ctypes.c_char_p), ctypes.c_int]
lib.spCompile.argtypes = [V]
lib.spGetDiagnosticOutput.restype = ctypes.c_char_p
lib.spGetDiagnosticOutput.argtypes = [V]
lib.spGetEntryPointCode.restype = V
lib.spGetEntryPointCode.argtypes = [V, ctypes.c_int, ctypes.POINTER(ctypes.c_size_t)]

args = sys.argv[1:]
req = lib.spCreateCompileRequest(lib.spCreateSession(None))
encoded = [a.encode() for a in args]
if lib.spProcessCommandLineArguments(req, (ctypes.c_char_p * len(encoded))(*encoded), len(encoded)) < 0:
    print(lib.spGetDiagnosticOutput(req).decode(), file=sys.stderr)
    sys.exit(2)
result = lib.spCompile(req)
diagnostics = lib.spGetDiagnosticOutput(req).decode()
if diagnostics:
    print(diagnostics, file=sys.stderr)
n = ctypes.c_size_t()
code = lib.spGetEntryPointCode(req, 0, ctypes.byref(n))
if result >= 0 and code and "-o" in args:
    with open(args[args.index("-o") + 1], "wb") as f:
        f.write(ctypes.string_at(code, n.value))
sys.exit(1 if result < 0 else 0)
