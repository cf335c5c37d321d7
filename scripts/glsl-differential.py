#!/usr/bin/env python3
"""Differential test of tessref's GLSL executor against a GL driver (Mesa llvmpipe).

Generates random, valid GLSL programs, draws each as one patch of a scene of draws, and runs the
scene on tessref (`tessref render --transform-feedback`) and on the driver (`tessref capture`).
Every value a program computes is recorded twice, at full float precision: by the tessellation
evaluation shader through transform feedback (its 32 bits as a uint), and by the fragment shader
through the colour buffer (the 32 bits split into bytes, one byte a channel, stored exactly by the
8-bit quantization). Each value is then checked against GLSL 4.50's precision for the statement
that computed it, on the inputs that side computed (docs/differential.md).

Standard library only. Usage:

    scripts/glsl-differential.py --count 10000 --seed 20250 [--jobs 2] [--keep-failures DIR]
"""

import argparse
import json
import math
import os
import random
import shutil
import struct
import subprocess
import sys
import tempfile
import threading
import time
import zlib
from concurrent.futures import ThreadPoolExecutor

# ------------------------------------------------------------------------------------------------
# float32 helpers

F32_MAX = 3.4028234663852886e38
MIN_NORMAL = 2.0 ** -126


def f32(x):
    """x rounded to the nearest float32 (ties to even), as a Python float."""
    return struct.unpack('<f', struct.pack('<f', x))[0]


def f32_bits(x):
    return struct.unpack('<I', struct.pack('<f', x))[0]


def bits_f32(b):
    return struct.unpack('<f', struct.pack('<I', b & 0xffffffff))[0]


def ulp(x):
    """The spacing of float32 numbers at |x| (GLSL's ULP of the exact result)."""
    a = abs(x)
    if a < MIN_NORMAL:
        return 2.0 ** -149
    if a >= F32_MAX:
        return 2.0 ** 104
    m, e = math.frexp(a)  # a = m * 2^e, m in [0.5, 1)
    return math.ldexp(1.0, e - 24)


def ordered(b):
    """float32 bits to an integer that orders like the floats (for ULP distances)."""
    return b if b < 0x80000000 else 0x80000000 - b


def ulp_distance(b1, b2):
    return abs(ordered(b1) - ordered(b2))


def i32(v):
    v &= 0xffffffff
    return v - (1 << 32) if v & 0x80000000 else v


def u32(v):
    return v & 0xffffffff


# ------------------------------------------------------------------------------------------------
# Error-tracked values: the exact (real) result of the operations from a side's inputs, and a bound
# on how far a conforming implementation's float may lie from it. Each operation adds GLSL 4.50's
# tolerance for it (section 4.7.1) and carries its inputs' bounds through its derivative.

LN2 = math.log(2.0)


class EF:
    __slots__ = ('x', 'e')

    def __init__(self, x, e=0.0):
        self.x = x
        self.e = e


class Domain(Exception):
    """An input outside the operation's domain (only where a side computed something else)."""


def cr(x):
    return 0.5 * ulp(x)  # correctly rounded


def ef_add(a, b):
    x = a.x + b.x
    return EF(x, a.e + b.e + cr(x))


def ef_sub(a, b):
    x = a.x - b.x
    return EF(x, a.e + b.e + cr(x))


def ef_mul(a, b):
    x = a.x * b.x
    return EF(x, abs(a.x) * b.e + abs(b.x) * a.e + a.e * b.e + cr(x))


def ef_neg(a):
    return EF(-a.x, a.e)


def ef_div(a, b):
    # a / b: 2.5 ULP for |b| in [2^-126, 2^126]
    if abs(b.x) - b.e <= 0:
        raise Domain('division by zero')
    x = a.x / b.x
    prop = (a.e + abs(x) * b.e) / (abs(b.x) - b.e)
    return EF(x, prop + 2.5 * ulp(x))


def ef_exp2(a, base_e=False):
    t = a.x * (1.0 / LN2) if base_e else a.x
    if t > 126 or t < -125:
        raise Domain('exp out of range')
    x = 2.0 ** t if not base_e else math.exp(a.x)
    de = a.e / LN2 if base_e else a.e
    prop = x * (2.0 ** de - 1.0) * 1.0000001
    return EF(x, prop + (3.0 + 2.0 * abs(a.x)) * ulp(x))


def ef_log2(a, base_e=False):
    if a.x - a.e <= 0:
        raise Domain('log of a value <= 0')
    x = math.log(a.x) if base_e else math.log2(a.x)
    prop = a.e / (a.x - a.e) * (1.0 if base_e else 1.0 / LN2)
    if 0.5 <= a.x <= 2.0:
        tol = 2.0 ** -21
    else:
        tol = 3.0 * ulp(x)
    return EF(x, prop + tol)


def ef_inversesqrt(a):
    if a.x - a.e <= 0:
        raise Domain('inversesqrt of a value <= 0')
    x = 1.0 / math.sqrt(a.x)
    prop = 0.5 * a.e / ((a.x - a.e) ** 1.5)
    return EF(x, prop + 2.0 * ulp(x))


def ef_sqrt(a):
    # inherited from 1.0 / inversesqrt(x)
    if a.x == 0 and a.e == 0:
        return EF(0.0, 0.0)
    return ef_div(EF(1.0), ef_inversesqrt(a))


def ef_pow(a, b):
    # inherited from exp2(y * log2(x))
    return ef_exp2(ef_mul(b, ef_log2(a)))


SIN_ABS = 2.0 ** -11  # Vulkan's sin/cos bound on [-pi, pi] (GLSL leaves it undefined)


def ef_sin(a, cosine=False):
    if abs(a.x) > math.pi + 1e-3:
        raise Domain('sin/cos outside [-pi, pi]')
    x = math.cos(a.x) if cosine else math.sin(a.x)
    return EF(x, a.e + SIN_ABS)


def ef_atan(a):
    # atan's derivative is at most 1. atan(0) is not generated: an earlier form of this bound
    # divided by zero there, and the run of record (seed 20250) was generated with it.
    if a.x == 0 and a.e == 0:
        raise Domain('atan(0)')
    x = math.atan(a.x)
    return EF(x, a.e + 4096 * ulp(x))


def ef_atan2(y, x):
    r = math.hypot(y.x, x.x)
    if r - (y.e + x.e) <= 0:
        raise Domain('atan(y, x) at the origin')
    v = math.atan2(y.x, x.x)
    prop = (y.e + x.e) / (r - (y.e + x.e))
    return EF(v, prop + 4096 * ulp(v))


def ef_exact(fn, *args):
    """A function GLSL defines exactly (floor, min, ...): its value at the exact argument; the
    bound is the argument's, where the function is 1-Lipschitz and continuous there."""
    return EF(fn(*[a.x for a in args]), max([a.e for a in args] + [0.0]))


def ef_floor_like(fn, a):
    # floor, ceil, trunc, roundEven: exact, but discontinuous: only for an exact argument
    if a.e != 0:
        raise Domain('floor of an inexact value')
    return EF(float(fn(a.x)), 0.0)


def round_even(x):
    r = round(x)  # Python rounds half to even
    return float(r)


def ef_fract(a):
    if a.e != 0:
        raise Domain('fract of an inexact value')
    fl = math.floor(a.x)
    return ef_sub(EF(a.x), EF(float(fl)))


def ef_sign(a):
    if a.e != 0 and abs(a.x) <= a.e:
        raise Domain('sign near 0')
    return EF(float((a.x > 0) - (a.x < 0)), 0.0)


def ef_dot(xs, ys):
    # inherited from x0*y0 + x1*y1 + ...: n products and n - 1 sums, each correctly rounded, in
    # whatever order (and fused or not): |error| <= n * u * sum |xi yi| (first order), u = 2^-24
    n = len(xs)
    s = 0.0
    mag = 0.0
    prop = 0.0
    for a, b in zip(xs, ys):
        s += a.x * b.x
        mag += abs(a.x * b.x)
        prop += abs(a.x) * b.e + abs(b.x) * a.e + a.e * b.e
    return EF(s, prop + (n * 2.0 ** -24 * 1.01) * (mag + prop) + cr(s))


def ef_length(xs):
    return ef_sqrt(ef_dot(xs, xs))


def ef_cross(a, b):
    return [ef_sub(ef_mul(a[1], b[2]), ef_mul(b[1], a[2])),
            ef_sub(ef_mul(a[2], b[0]), ef_mul(b[2], a[0])),
            ef_sub(ef_mul(a[0], b[1]), ef_mul(b[0], a[1]))]


def ef_mix(x, y, a):
    # x * (1 - a) + y * a
    return ef_add(ef_mul(x, ef_sub(EF(1.0), a)), ef_mul(y, a))


def ef_clamp(x, lo, hi):
    return EF(min(max(x.x, lo.x), hi.x), max(x.e, lo.e, hi.e))


def ef_step(edge, x):
    if abs(x.x - edge.x) <= x.e + edge.e and (x.e or edge.e):
        raise Domain('step at its edge')
    return EF(0.0 if x.x < edge.x else 1.0)


def ef_smoothstep(e0, e1, x):
    # t = clamp((x - e0) / (e1 - e0), 0, 1); t * t * (3 - 2 * t)
    t = ef_clamp(ef_div(ef_sub(x, e0), ef_sub(e1, e0)), EF(0.0), EF(1.0))
    return ef_mul(ef_mul(t, t), ef_sub(EF(3.0), ef_mul(EF(2.0), t)))


def ef_fma(a, b, c):
    # inherited from a * b + c: one correctly rounded operation or two
    return ef_add(ef_mul(a, b), c)


def ef_mod_alternatives(x, y):
    """mod(x, y) = x - y * floor(x / y): the quotient may round across an integer, so each
    floor the division's tolerance allows gives an acceptable result."""
    q = ef_div(x, y)
    nominal = math.floor(f32(q.x))  # first: the floor of the correctly rounded quotient
    ks = [nominal] + sorted({math.floor(q.x - q.e), math.floor(q.x), math.floor(q.x + q.e)} - {nominal})
    return [ef_sub(x, ef_mul(y, EF(float(k)))) for k in ks]


# ------------------------------------------------------------------------------------------------
# The program: typed variables, statements, and their evaluation

FLOAT_TYPES = {'float': 1, 'vec2': 2, 'vec3': 3, 'vec4': 4}
INT_TYPES = {'int': 1, 'uint': 1}
SWZ = 'xyzw'

CONSTS = [0.5, 2.0, 3.0, 0.25, 1.5, -1.0, 0.1, 0.75, -2.5, 10.0, 0.001, 7.0, 1.0, 0.3333]


def vtype(kind, n):
    return kind if n == 1 else {'float': 'vec', 'int': 'ivec', 'uint': 'uvec'}[kind] + str(n)


def ncomp(t):
    return FLOAT_TYPES.get(t, 1)


def is_float(t):
    return t in FLOAT_TYPES


def fmt_float(v):
    s = repr(float(v))
    if 'e' not in s and '.' not in s:
        s += '.0'
    return s


_TLS = threading.local()


def generating():
    """True while this thread generates programs: then every arm of a branch must be valid."""
    return getattr(_TLS, 'generating', False)


class Ctx:
    """Evaluation of one program at one point, on one side's recorded values or nominally."""

    def __init__(self, values):
        self.v = values  # name -> list of components (EF for floats, int for ints)


# A statement: its result variable, type, GLSL text (a list of lines) and an evaluator that
# returns, per component, a list of acceptable results (EF alternatives, or exact ints).

class Stmt:
    def __init__(self, name, typ, op, lines, fn, reads):
        self.name = name
        self.typ = typ
        self.op = op          # the operation's name, for the report
        self.lines = lines
        self.fn = fn          # fn(env) -> list (per component) of alternatives
        self.reads = reads    # variables read


def comp(env, ref):
    """A component reference: ('var', name, index) or ('const', value) -> EF or int."""
    if ref[0] == 'const':
        return EF(ref[1]) if isinstance(ref[1], float) else ref[1]
    return env[ref[1]][ref[2]]


class Gen:
    def __init__(self, rng, npoints, nfloat_in, nint_in):
        self.rng = rng
        self.vars = []       # (name, type)
        self.stmts = []
        self.np = npoints
        self.nf = nfloat_in
        self.ni = nint_in
        self.count = 0
        self.words = 0

    # -- operand choice -------------------------------------------------------------------------
    def pick(self, typ):
        c = [n for n, t in self.vars if t == typ]
        return self.rng.choice(c) if c else None

    def pick_float(self, n):
        return self.pick(vtype('float', n))

    def new_name(self):
        self.count += 1
        return 'v%d' % self.count


def mk_inputs(rng, npoints, nf, ni):
    fl = []
    for _ in range(npoints * nf):
        r = rng.random()
        if r < 0.15:
            v = float(rng.randint(-8, 8))
        elif r < 0.25:
            v = rng.choice([0.5, -0.5, 0.25, 1.0, -1.0, 2.0, 0.125])
        else:
            v = rng.uniform(0.5, 1.0) * 2.0 ** rng.randint(-6, 6) * rng.choice([1, -1])
        fl.append(f32(v))
    it = []
    for _ in range(npoints * ni):
        r = rng.random()
        if r < 0.7:
            it.append(rng.randint(-100, 100))
        elif r < 0.85:
            it.append(rng.randint(0, 31))
        else:
            it.append(i32(rng.getrandbits(32)))
    return fl, it


# ------------------------------------------------------------------------------------------------
# Operations. Each maker returns (op, type, expr_text, evaluator over the env, reads) or None.
# The evaluator takes the env of component lists and returns a list of per-component alternatives.

def fvar_comps(env, name):
    return env[name]


def elementwise(fn, *arglists):
    n = max(len(a) for a in arglists)
    out = []
    for i in range(n):
        args = [a[i] if len(a) > 1 else a[0] for a in arglists]
        r = fn(*args)
        out.append(r if isinstance(r, list) else [r])
    return out


FLOAT_UNARY = {
    # name: (evaluator on EF, domain check on the nominal value, weight)
    'abs': (lambda a: ef_exact(abs, a), lambda x: True),
    'floor': (lambda a: ef_floor_like(math.floor, a), lambda x: True),
    'ceil': (lambda a: ef_floor_like(math.ceil, a), lambda x: True),
    'trunc': (lambda a: ef_floor_like(math.trunc, a), lambda x: True),
    'roundEven': (lambda a: ef_floor_like(round_even, a), lambda x: True),
    'fract': (ef_fract, lambda x: True),
    'sign': (ef_sign, lambda x: True),
    'sqrt': (ef_sqrt, lambda x: x >= 1e-6),
    'inversesqrt': (ef_inversesqrt, lambda x: x >= 1e-6),
    'exp': (lambda a: ef_exp2(a, True), lambda x: abs(x) <= 20),
    'exp2': (ef_exp2, lambda x: abs(x) <= 30),
    'log': (lambda a: ef_log2(a, True), lambda x: x >= 1e-6),
    'log2': (ef_log2, lambda x: x >= 1e-6),
    'sin': (ef_sin, lambda x: abs(x) <= 3.14),
    'cos': (lambda a: ef_sin(a, True), lambda x: abs(x) <= 3.14),
    'atan': (ef_atan, lambda x: True),
    '-': (ef_neg, lambda x: True),
}


def in_range(vals):
    """A nominal float result the generator accepts: finite, and 0 or in [1e-12, 1e12]."""
    for v in vals:
        if v != v or abs(v) > 1e12 or (v != 0 and abs(v) < 1e-12):
            return False
    return True


class Program:
    """One generated program: inputs, statements, the words it records."""

    def __init__(self, rng, pid):
        self.pid = pid
        self.rng = rng
        self.npoints = 16  # quads at level 3: (3 + 1)^2 domain points
        self.nf = 6
        self.ni = 3
        self.fin, self.iin = mk_inputs(rng, self.npoints, self.nf, self.ni)
        self.vars = []    # (name, type)
        self.stmts = []
        self.count = 0
        self.words = []   # (stmt index, component)
        # nominal environments, one per point
        self.nominal = []
        for p in range(self.npoints):
            env = {}
            for k in range(self.nf):
                env['f%d' % k] = [EF(self.fin[p * self.nf + k])]
            for k in range(self.ni):
                env['i%d' % k] = [self.iin[p * self.ni + k]]
            self.nominal.append(env)
        for k in range(self.nf):
            self.vars.append(('f%d' % k, 'float'))
        for k in range(self.ni):
            self.vars.append(('i%d' % k, 'int'))

    # -- helpers ------------------------------------------------------------------------------
    def pick(self, typ, exclude=()):
        c = [n for n, t in self.vars if t == typ and n not in exclude]
        return self.rng.choice(c) if c else None

    def const(self):
        return f32(self.rng.choice(CONSTS))

    def try_add(self, typ, op, lines_fn, fn, reads, max_words):
        """Evaluates the candidate at every point nominally; keeps it if it is valid there."""
        n = ncomp(typ)
        if len(self.words) + n > max_words:
            return False
        results = []
        try:
            for env in self.nominal:
                alts = fn(env)
                if len(alts) != n:
                    raise AssertionError('component count')
                comps = []
                for a in alts:
                    a0 = a[0]
                    if isinstance(a0, EF):
                        x = f32(a0.x) if abs(a0.x) < F32_MAX else float('inf')
                        comps.append(x)
                    else:
                        comps.append(a0)
                if is_float(typ) and not in_range(comps):
                    return False
                results.append(comps)
        except (Domain, OverflowError, ValueError, ZeroDivisionError):
            return False
        self.count += 1
        name = 'v%d' % self.count
        st = Stmt(name, typ, op, lines_fn(name), fn, reads)
        self.stmts.append(st)
        for env, comps in zip(self.nominal, results):
            env[name] = [EF(c) for c in comps] if is_float(typ) else comps
        self.vars.append((name, typ))
        for c in range(n):
            self.words.append((len(self.stmts) - 1, c))
        return True

    # -- statement makers: each picks operands, builds the GLSL and the evaluator ---------------
    def gen_statement(self, max_words):
        r = self.rng
        makers = [
            (self.m_arith, 14), (self.m_unary, 14), (self.m_binary_builtin, 8),
            (self.m_vector, 8), (self.m_geometric, 6), (self.m_int, 10), (self.m_convert, 7),
            (self.m_select, 5), (self.m_if, 6), (self.m_switch, 3), (self.m_loop, 7),
            (self.m_swizzle, 4), (self.m_bits, 3),
        ]
        total = sum(w for _, w in makers)
        for _ in range(40):
            x = r.uniform(0, total)
            for m, w in makers:
                x -= w
                if x <= 0:
                    break
            if m(max_words):
                return True
        return False

    def ftype(self):
        return self.rng.choice(['float', 'float', 'float', 'vec2', 'vec3', 'vec4'])

    def m_arith(self, mw):
        r = self.rng
        t = self.ftype()
        a = self.pick(t)
        if a is None:
            return False
        op = r.choice(['+', '-', '*', '/', '*s', '/s', '+c', '*c'])
        if op in ('*s', '/s'):
            b = self.pick('float')
            bt = 'float'
        elif op in ('+c', '*c'):
            b = None
        else:
            b = self.pick(t)
            bt = t
        if op in ('+c', '*c'):
            c = self.const()
            sym = op[0]
            fn_ = {'+': ef_add, '*': ef_mul}[sym]
            text = '%s %s %s' % (a, sym, fmt_float(c))
            fn = lambda env: elementwise(lambda x: fn_(x, EF(c)), env[a])
            reads = [a]
        else:
            sym = op[0]
            fn_ = {'+': ef_add, '-': ef_sub, '*': ef_mul, '/': ef_div}[sym]
            text = '%s %s %s' % (a, sym, b)
            fn = lambda env: elementwise(fn_, env[a], env[b])
            reads = [a, b]
            if sym == '/':
                def fn(env, fn_=fn_):
                    for d in env[b]:
                        if abs(d.x) < 1e-4:
                            raise Domain('small divisor')
                    return elementwise(fn_, env[a], env[b])
        return self.try_add(t, sym, lambda n: ['precise %s %s = %s;' % (t, n, text)], fn, reads, mw)

    # Operand adapters for functions with a limited domain, tried when the operand itself is
    # outside it at some point: (GLSL with %s for the operand, evaluator on one EF component)
    ADAPT = {
        'positive': ('(abs(%s) + 0.25)', lambda x: ef_add(ef_exact(abs, x), EF(0.25))),
        'angle': ('(fract(%s) * 6.25 - 3.125)', lambda x: ef_sub(ef_mul(ef_fract(x), EF(6.25)), EF(3.125))),
        'exponent': ('clamp(%s, -20.0, 20.0)', lambda x: ef_clamp(x, EF(-20.0), EF(20.0))),
        'small': ('clamp(%s, -4.0, 4.0)', lambda x: ef_clamp(x, EF(-4.0), EF(4.0))),
    }
    UNARY_ADAPTER = {'sqrt': 'positive', 'inversesqrt': 'positive', 'log': 'positive', 'log2': 'positive',
                     'sin': 'angle', 'cos': 'angle', 'exp': 'exponent', 'exp2': 'exponent'}

    def m_unary(self, mw):
        r = self.rng
        t = self.ftype()
        a = self.pick(t)
        if a is None:
            return False
        name = r.choice(list(FLOAT_UNARY))
        ev, dom = FLOAT_UNARY[name]
        for adapt in (None, self.UNARY_ADAPTER.get(name)):
            if adapt is None:
                arg = a
                pre = lambda x: x
            else:
                arg = self.ADAPT[adapt][0] % a
                pre = self.ADAPT[adapt][1]

            def fn(env, pre=pre):
                comps = [pre(c) for c in env[a]]
                for c in comps:
                    if not dom(c.x):
                        raise Domain(name)
                return elementwise(ev, comps)
            text = '-%s' % arg if name == '-' else '%s(%s)' % (name, arg)
            if self.try_add(t, name if name != '-' else 'negate',
                            lambda n, text=text: ['precise %s %s = %s;' % (t, n, text)], fn, [a], mw):
                return True
            if name not in self.UNARY_ADAPTER:
                return False
        return False

    def m_binary_builtin(self, mw):
        r = self.rng
        t = self.ftype()
        a = self.pick(t)
        if a is None:
            return False
        name = r.choice(['min', 'max', 'pow', 'atan2', 'mod', 'step', 'mix', 'clamp',
                         'smoothstep', 'fma', 'mins', 'maxs'])
        b = self.pick(t)
        if name in ('mins', 'maxs'):
            b = self.pick('float')
            fn_ = {'mins': lambda x, y: ef_exact(min, x, y), 'maxs': lambda x, y: ef_exact(max, x, y)}[name]
            text = '%s(%s, %s)' % (name[:3], a, b)
            fn = lambda env: elementwise(fn_, env[a], env[b])
            name = name[:3]
            reads = [a, b]
        elif name in ('min', 'max'):
            fn_ = {'min': lambda x, y: ef_exact(min, x, y), 'max': lambda x, y: ef_exact(max, x, y)}[name]
            text = '%s(%s, %s)' % (name, a, b)
            fn = lambda env: elementwise(fn_, env[a], env[b])
            reads = [a, b]
        elif name == 'pow':
            # pow(|x| + 0.25, clamp(y, -4, 4)): GLSL leaves x < 0 and x = 0 with y <= 0 undefined
            def fn(env):
                xs = [self.ADAPT['positive'][1](x) for x in env[a]]
                ys = [self.ADAPT['small'][1](y) for y in env[b]]
                for x in xs:
                    if x.x > 1e3:
                        raise Domain('pow')
                return elementwise(ef_pow, xs, ys)
            text = 'pow(%s, %s)' % (self.ADAPT['positive'][0] % a, self.ADAPT['small'][0] % b)
            reads = [a, b]
        elif name == 'atan2':
            def fn(env):
                for y, x in zip(env[a], env[b]):
                    if abs(x.x) + abs(y.x) < 1e-3:
                        raise Domain('atan2')
                return elementwise(ef_atan2, env[a], env[b])
            text = 'atan(%s, %s)' % (a, b)
            reads = [a, b]
        elif name == 'mod':
            def fn(env):
                for x, y in zip(env[a], env[b]):
                    if abs(y.x) < 1e-2 or abs(x.x / y.x) > 1e5:
                        raise Domain('mod')
                return elementwise(ef_mod_alternatives, env[a], env[b])
            text = 'mod(%s, %s)' % (a, b)
            reads = [a, b]
        elif name == 'step':
            fn = lambda env: elementwise(ef_step, env[a], env[b])
            text = 'step(%s, %s)' % (a, b)
            reads = [a, b]
        elif name == 'mix':
            c = self.pick(t if r.random() < 0.5 else 'float')
            fn = lambda env: elementwise(ef_mix, env[a], env[b], env[c])
            text = 'mix(%s, %s, %s)' % (a, b, c)
            reads = [a, b, c]
        elif name == 'fma':
            c = self.pick(t)
            fn = lambda env: elementwise(ef_fma, env[a], env[b], env[c])
            text = 'fma(%s, %s, %s)' % (a, b, c)
            reads = [a, b, c]
        elif name == 'clamp':
            lo = f32(r.choice([-2.0, -1.0, 0.0, 0.25, -0.5]))
            hi = f32(lo + r.choice([0.5, 1.0, 3.0, 10.0]))
            fn = lambda env: elementwise(lambda x: ef_clamp(x, EF(lo), EF(hi)), env[a])
            text = 'clamp(%s, %s, %s)' % (a, fmt_float(lo), fmt_float(hi))
            reads = [a]
        else:  # smoothstep
            e0 = f32(r.choice([-2.0, -1.0, 0.0, 0.5]))
            e1 = f32(e0 + r.choice([0.5, 1.0, 3.0, 7.0]))
            fn = lambda env: elementwise(lambda x: ef_smoothstep(EF(e0), EF(e1), x), env[a])
            text = 'smoothstep(%s, %s, %s)' % (fmt_float(e0), fmt_float(e1), a)
            reads = [a]
        if any(x is None for x in reads):
            return False
        return self.try_add(t, name, lambda n: ['precise %s %s = %s;' % (t, n, text)], fn, reads, mw)

    def m_vector(self, mw):
        """A vector built from scalars and other vectors."""
        r = self.rng
        n = r.choice([2, 3, 4])
        t = vtype('float', n)
        parts = []
        refs = []
        left = n
        while left > 0:
            k = r.randint(1, left)
            src = self.pick(vtype('float', k))
            if src is None:
                k = 1
                src = self.pick('float')
            if k == 1:
                parts.append(src)
                refs.append((src, 0))
            else:
                parts.append(src)
                refs.extend((src, i) for i in range(k))
            left -= k
        fn = lambda env: [[env[s][i]] for s, i in refs]
        text = '%s(%s)' % (t, ', '.join(parts))
        return self.try_add(t, 'constructor', lambda nm: ['precise %s %s = %s;' % (t, nm, text)],
                            fn, list({s for s, _ in refs}), mw)

    def m_swizzle(self, mw):
        r = self.rng
        n = r.choice([2, 3, 4])
        src = self.pick(vtype('float', n))
        if src is None:
            return False
        k = r.choice([1, 2, 3, 4])
        idx = [r.randrange(n) for _ in range(k)]
        t = vtype('float', k)
        fn = lambda env: [[env[src][i]] for i in idx]
        text = '%s.%s' % (src, ''.join(SWZ[i] for i in idx))
        return self.try_add(t, 'swizzle', lambda nm: ['precise %s %s = %s;' % (t, nm, text)],
                            fn, [src], mw)

    def m_geometric(self, mw):
        r = self.rng
        n = r.choice([2, 3, 4])
        t = vtype('float', n)
        a = self.pick(t)
        b = self.pick(t)
        if a is None:
            return False
        name = r.choice(['dot', 'length', 'distance', 'normalize', 'cross'])
        if name == 'cross':
            a = self.pick('vec3')
            b = self.pick('vec3')
            if a is None:
                return False
            fn = lambda env: [[c] for c in ef_cross(env[a], env[b])]
            return self.try_add('vec3', 'cross', lambda nm: ['precise vec3 %s = cross(%s, %s);' % (nm, a, b)],
                                fn, [a, b], mw)
        if name == 'dot':
            fn = lambda env: [[ef_dot(env[a], env[b])]]
            text, rt, reads = 'dot(%s, %s)' % (a, b), 'float', [a, b]
        elif name == 'length':
            fn = lambda env: [[ef_length(env[a])]]
            text, rt, reads = 'length(%s)' % a, 'float', [a]
        elif name == 'distance':
            fn = lambda env: [[ef_length([ef_sub(x, y) for x, y in zip(env[a], env[b])])]]
            text, rt, reads = 'distance(%s, %s)' % (a, b), 'float', [a, b]
        else:
            def fn(env):
                ln = ef_length(env[a])
                if ln.x < 1e-3:
                    raise Domain('normalize of a short vector')
                return [[ef_div(x, ln)] for x in env[a]]
            text, rt, reads = 'normalize(%s)' % a, t, [a]
        return self.try_add(rt, name, lambda nm: ['precise %s %s = %s;' % (rt, nm, text)], fn, reads, mw)

    def ipick(self):
        t = self.rng.choice(['int', 'int', 'uint'])
        a = self.pick(t)
        if a is None:
            t = 'int'
            a = self.pick(t)
        return t, a

    def m_int(self, mw):
        r = self.rng
        t, a = self.ipick()
        b = self.pick(t)
        wrap = i32 if t == 'int' else u32
        op = r.choice(['+', '-', '*', '&', '|', '^', '<<', '>>', '/', '%', '~', 'min', 'max', 'abs', '*c'])
        if op in ('<<', '>>'):
            if r.random() < 0.5:
                s = r.randint(0, 31)
                text = '%s %s %d' % (a, op, s)
                sh = lambda env: s
                reads = [a]
            else:
                text = '%s %s (%s & %s)' % (a, op, b, '31' if t == 'int' else '31u')
                sh = lambda env: env[b][0] & 31
                reads = [a, b]
            if op == '<<':
                fn = lambda env: [[wrap(env[a][0] << sh(env))]]
            else:
                fn = lambda env: [[wrap(env[a][0] >> sh(env))]]  # Python >>: arithmetic on int
        elif op in ('/', '%'):
            def fn(env):
                x, y = env[a][0], env[b][0]
                if x < 0 or y <= 0:
                    raise Domain('integer division of negative values')
                return [[x // y if op == '/' else x % y]]
            text = '%s %s %s' % (a, op, b)
            reads = [a, b]
        elif op == '~':
            fn = lambda env: [[wrap(~env[a][0])]]
            text = '~%s' % a
            reads = [a]
        elif op == 'abs':
            if t != 'int':
                return False
            def fn(env):
                if env[a][0] == -2 ** 31:
                    raise Domain('abs(INT_MIN)')
                return [[abs(env[a][0])]]
            text = 'abs(%s)' % a
            reads = [a]
        elif op in ('min', 'max'):
            f = min if op == 'min' else max
            fn = lambda env: [[f(env[a][0], env[b][0])]]
            text = '%s(%s, %s)' % (op, a, b)
            reads = [a, b]
        elif op == '*c':
            c = r.choice([3, 7, -5, 1103515245, 65599]) if t == 'int' else r.choice([3, 7, 2654435761])
            fn = lambda env: [[wrap(env[a][0] * c)]]
            text = '%s * %s' % (a, str(c) + ('u' if t == 'uint' else ''))
            reads = [a]
        else:
            f = {'+': lambda x, y: x + y, '-': lambda x, y: x - y, '*': lambda x, y: x * y,
                 '&': lambda x, y: x & y, '|': lambda x, y: x | y, '^': lambda x, y: x ^ y}[op]
            fn = lambda env: [[wrap(f(env[a][0], env[b][0]))]]
            text = '%s %s %s' % (a, op, b)
            reads = [a, b]
        if any(x is None for x in reads):
            return False
        opname = {'*c': '*', '<<': '<<', '>>': '>>'}.get(op, op)
        return self.try_add(t, 'int ' + opname, lambda n: ['%s %s = %s;' % (t, n, text)], fn, reads, mw)

    def m_convert(self, mw):
        r = self.rng
        kind = r.choice(['float(int)', 'float(uint)', 'int(float)', 'uint(float)', 'uint(int)', 'int(uint)'])
        if kind == 'float(int)' or kind == 'float(uint)':
            st = 'int' if kind == 'float(int)' else 'uint'
            a = self.pick(st)
            if a is None:
                return False
            fn = lambda env: [[EF(float(env[a][0]), cr(float(env[a][0])))]]
            return self.try_add('float', kind, lambda n: ['precise float %s = float(%s);' % (n, a)], fn, [a], mw)
        if kind in ('int(float)', 'uint(float)'):
            a = self.pick('float')
            dt = kind[:kind.index('(')]

            def fn(env):
                x = env[a][0].x
                lo = -1e9 if dt == 'int' else 0.0
                if not (lo <= x <= 1e9):
                    raise Domain(kind)
                return [[int(math.trunc(x))]]
            return self.try_add(dt, kind, lambda n: ['%s %s = %s(%s);' % (dt, n, dt, a)], fn, [a], mw)
        st, dt = ('int', 'uint') if kind == 'uint(int)' else ('uint', 'int')
        a = self.pick(st)
        if a is None:
            return False
        wrap = u32 if dt == 'uint' else i32
        fn = lambda env: [[wrap(env[a][0])]]
        return self.try_add(dt, kind, lambda n: ['%s %s = %s(%s);' % (dt, n, dt, a)], fn, [a], mw)

    def m_bits(self, mw):
        r = self.rng
        a = self.pick('float')
        k = self.pick('int')
        if a is None or k is None:
            return False
        if r.random() < 0.5:
            def fn(env):
                return [[i32(f32_bits(env[a][0].x))]]
            return self.try_add('int', 'floatBitsToInt', lambda n: ['int %s = floatBitsToInt(%s);' % (n, a)],
                                fn, [a], mw)

        def fn(env):
            b = f32_bits(env[a][0].x) ^ (env[k][0] & 0xff)
            return [[EF(bits_f32(b))]]
        return self.try_add('float', 'intBitsToFloat',
                            lambda n: ['precise float %s = intBitsToFloat(floatBitsToInt(%s) ^ (%s & 255));' % (n, a, k)],
                            fn, [a, k], mw)

    # -- conditions and control flow -----------------------------------------------------------
    def cond(self):
        """A condition on recorded values: (text, evaluator, reads)."""
        r = self.rng
        if r.random() < 0.5:
            a = self.pick('float')
            b = self.pick('float')
            op = r.choice(['<', '>', '<=', '>='])
            f = {'<': lambda x, y: x < y, '>': lambda x, y: x > y, '<=': lambda x, y: x <= y,
                 '>=': lambda x, y: x >= y}[op]
            return ('%s %s %s' % (a, op, b), lambda env: f(env[a][0].x, env[b][0].x), [a, b])
        a = self.pick('int')
        m = r.choice([1, 3, 4])
        if r.random() < 0.5:
            b = self.pick('int')
            return ('%s < %s || (%s & %d) == 0' % (a, b, a, m),
                    lambda env: env[a][0] < env[b][0] or (env[a][0] & m) == 0, [a, b])
        return ('(%s & %d) != 0' % (a, m), lambda env: (env[a][0] & m) != 0, [a])

    def arm(self, t):
        """An expression of type t for one arm of an if or switch: (text, evaluator, reads, op)."""
        r = self.rng
        a = self.pick(t)
        b = self.pick(t)
        if is_float(t):
            sym = r.choice(['+', '-', '*', 'sqrt', 'exp2', 'max', 'abs'])
            if sym in ('+', '-', '*'):
                f = {'+': ef_add, '-': ef_sub, '*': ef_mul}[sym]
                return ('%s %s %s' % (a, sym, b), lambda env: elementwise(f, env[a], env[b]), [a, b], sym)
            if sym == 'sqrt':
                return ('sqrt(abs(%s))' % a, lambda env: elementwise(lambda x: ef_sqrt(ef_exact(abs, x)), env[a]),
                        [a], 'sqrt')
            if sym == 'exp2':
                def fn(env):
                    for c in env[a]:
                        if abs(c.x) > 30:
                            raise Domain('exp2')
                    return elementwise(ef_exp2, env[a])
                return ('exp2(%s)' % a, fn, [a], 'exp2')
            if sym == 'max':
                return ('max(%s, %s)' % (a, b), lambda env: elementwise(lambda x, y: ef_exact(max, x, y), env[a], env[b]),
                        [a, b], 'max')
            return ('abs(%s)' % a, lambda env: elementwise(lambda x: ef_exact(abs, x), env[a]), [a], 'abs')
        wrap = i32 if t == 'int' else u32
        sym = r.choice(['+', '^', '*'])
        f = {'+': lambda x, y: x + y, '^': lambda x, y: x ^ y, '*': lambda x, y: x * y}[sym]
        return ('%s %s %s' % (a, sym, b), lambda env: [[wrap(f(env[a][0], env[b][0]))]], [a, b], 'int ' + sym)

    def m_select(self, mw):
        t = self.rng.choice(['float', 'vec2', 'vec3', 'int', 'uint'])
        a = self.pick(t)
        b = self.pick(t)
        if a is None or b is None:
            return False
        ctext, cfn, creads = self.cond()
        if None in creads:
            return False
        fn = lambda env: [[c] for c in (env[a] if cfn(env) else env[b])]
        pre = 'precise ' if is_float(t) else ''
        return self.try_add(t, '?:', lambda n: ['%s%s %s = (%s) ? %s : %s;' % (pre, t, n, ctext, a, b)],
                            fn, creads + [a, b], mw)

    def m_if(self, mw):
        t = self.rng.choice(['float', 'vec3', 'int', 'uint'])
        if self.pick(t) is None:
            return False
        ctext, cfn, creads = self.cond()
        if None in creads:
            return False
        t1, f1, r1, o1 = self.arm(t)
        t2, f2, r2, o2 = self.arm(t)
        if None in r1 or None in r2:
            return False
        pre = 'precise ' if is_float(t) else ''

        def fn(env):
            # both arms must be valid wherever the branch could go: the generator checks both
            if generating():
                a1 = f1(env)
                a2 = f2(env)
                return a1 if cfn(env) else a2
            return f1(env) if cfn(env) else f2(env)

        def lines(n):
            return ['%s%s %s;' % (pre, t, n), 'if (%s) {' % ctext, '  %s = %s;' % (n, t1),
                    '} else {', '  %s = %s;' % (n, t2), '}']
        return self.try_add(t, 'if/else', lines, fn, creads + r1 + r2, mw)

    def m_switch(self, mw):
        t = self.rng.choice(['float', 'int'])
        sel = self.pick('int')
        if sel is None or self.pick(t) is None:
            return False
        arms = [self.arm(t) for _ in range(3)]
        if any(None in a[2] for a in arms):
            return False
        pre = 'precise ' if is_float(t) else ''

        def fn(env):
            k = min(env[sel][0] & 3, 2)
            if generating():
                res = [a[1](env) for a in arms]
                return res[k]
            return arms[k][1](env)

        def lines(n):
            out = ['%s%s %s;' % (pre, t, n), 'switch (%s & 3) {' % sel]
            out += ['case 0:', '  %s = %s;' % (n, arms[0][0]), '  break;']
            out += ['case 1:', '  %s = %s;' % (n, arms[1][0]), '  break;']
            out += ['default:', '  %s = %s;' % (n, arms[2][0]), '  break;', '}']
            return out
        reads = [sel] + [x for a in arms for x in a[2]]
        return self.try_add(t, 'switch', lines, fn, reads, mw)

    def m_loop(self, mw):
        """A loop with a bounded trip count carrying one accumulator."""
        r = self.rng
        t = r.choice(['float', 'float', 'vec2', 'int', 'uint'])
        init = self.pick(t)
        if init is None:
            return False
        kvar = self.pick('int')
        style = r.choice(['const', 'var', 'break', 'continue', 'while'])
        nconst = r.randint(1, 6)
        if is_float(t):
            x = self.pick(t)
            body = r.choice(['acc + x', 'acc * c', 'acc - float(k)', 'abs(acc - x) * c', 'mix(acc, x, c)',
                             'max(acc, x) * c + float(k)'])
            c = f32(r.choice([0.5, 0.75, 1.25, -0.5, 0.9]))
            ctext = fmt_float(c)

            def step(env, acc, k):
                xv = env[x]
                if body == 'acc + x':
                    return [ef_add(p, q) for p, q in zip(acc, xv)]
                if body == 'acc * c':
                    return [ef_mul(p, EF(c)) for p in acc]
                if body == 'acc - float(k)':
                    return [ef_sub(p, EF(float(k))) for p in acc]
                if body == 'abs(acc - x) * c':
                    return [ef_mul(ef_exact(abs, ef_sub(p, q)), EF(c)) for p, q in zip(acc, xv)]
                if body == 'mix(acc, x, c)':
                    return [ef_mix(p, q, EF(c)) for p, q in zip(acc, xv)]
                return [ef_add(ef_mul(ef_exact(max, p, q), EF(c)), EF(float(k))) for p, q in zip(acc, xv)]
            btext = body.replace('acc', 'ACC').replace('x', x).replace('c', ctext).replace('k', 'KK')
            btext = btext.replace('ACC', 'acc').replace('KK', 'k').replace('abs', 'abs').replace('ma' + ctext, 'max')
            # rebuild carefully: the replacements above must not touch function names
            btext = {'acc + x': 'ACC + %s' % x, 'acc * c': 'ACC * %s' % ctext,
                     'acc - float(k)': 'ACC - float(k)', 'abs(acc - x) * c': 'abs(ACC - %s) * %s' % (x, ctext),
                     'mix(acc, x, c)': 'mix(ACC, %s, %s)' % (x, ctext),
                     'max(acc, x) * c + float(k)': 'max(ACC, %s) * %s + float(k)' % (x, ctext)}[body]
            reads_body = [x]
            opname = 'loop: ' + body.replace('acc', 'a').replace(' ', '')
        else:
            x = self.pick(t)
            wrap = i32 if t == 'int' else u32
            body = r.choice(['acc * 3 + k', 'acc ^ (acc << 5)', 'acc + x', '(acc >> 1) ^ x'])
            kk = 'k' if t == 'int' else 'uint(k)'
            btext = {'acc * 3 + k': 'ACC * %s + %s' % ('3' if t == 'int' else '3u', kk),
                     'acc ^ (acc << 5)': 'ACC ^ (ACC << 5)', 'acc + x': 'ACC + %s' % x,
                     '(acc >> 1) ^ x': '(ACC >> 1) ^ %s' % x}[body]

            def step(env, acc, k):
                a = acc[0]
                if body == 'acc * 3 + k':
                    return [wrap(a * 3 + k)]
                if body == 'acc ^ (acc << 5)':
                    return [wrap(a ^ (a << 5))]
                if body == 'acc + x':
                    return [wrap(a + env[x][0])]
                return [wrap((a >> 1) ^ env[x][0])]
            reads_body = [x]
            opname = 'loop: int ' + body.replace('acc', 'a').replace(' ', '')
        if kvar is None and style != 'const':
            style = 'const'

        def trip(env):
            return nconst if style in ('const', 'break', 'continue') else (env[kvar][0] & 3) + 1

        def fn(env):
            acc = list(env[init])
            n = trip(env)
            brk = (env[kvar][0] & 3) if style == 'break' else None
            skip = (env[kvar][0] & 3) if style == 'continue' else None
            for k in range(n):
                if brk is not None and k == brk:
                    break
                if skip is not None and k == skip:
                    continue
                acc = step(env, acc, k)
                if is_float(t):
                    for a in acc:
                        if abs(a.x) > 1e12:
                            raise Domain('loop overflow')
            return [[a] for a in acc]

        pre = 'precise ' if is_float(t) else ''

        def lines(n):
            b = btext.replace('ACC', n)
            out = ['%s%s %s = %s;' % (pre, t, n, init)]
            if style == 'while':
                out += ['{', '  int k = 0;', '  while (k < (%s & 3) + 1) {' % kvar, '    %s = %s;' % (n, b),
                        '    k++;', '  }', '}']
                return out
            bound = str(nconst) if style != 'var' else '(%s & 3) + 1' % kvar
            out += ['for (int k = 0; k < %s; ++k) {' % bound]
            if style == 'break':
                out += ['  if (k == (%s & 3)) break;' % kvar]
            if style == 'continue':
                out += ['  if (k == (%s & 3)) continue;' % kvar]
            out += ['  %s = %s;' % (n, b), '}']
            return out
        reads = [init] + reads_body + ([kvar] if kvar else [])
        if None in reads:
            return False
        return self.try_add(t, opname, lines, fn, reads, mw)

    # -- the whole program --------------------------------------------------------------------
    def generate(self, nstmts, max_words):
        for _ in range(nstmts):
            if not self.gen_statement(max_words):
                break

    def uniforms(self):
        return {'u_f': [float(v) for v in self.fin], 'u_i': list(self.iin)}

    def body_glsl(self):
        nw = len(self.words)
        out = ['uniform float u_f[%d];' % (self.npoints * self.nf),
               'uniform int u_i[%d];' % (self.npoints * self.ni),
               'void dt_compute(int p, out uint w[%d]) {' % nw]
        for k in range(self.nf):
            out.append('  precise float f%d = u_f[p * %d + %d];' % (k, self.nf, k))
        for k in range(self.ni):
            out.append('  int i%d = u_i[p * %d + %d];' % (k, self.ni, k))
        wi = 0
        for st in self.stmts:
            for ln in st.lines:
                out.append('  ' + ln)
            n = ncomp(st.typ)
            for c in range(n):
                ref = st.name if n == 1 else '%s.%s' % (st.name, SWZ[c])
                if is_float(st.typ):
                    out.append('  w[%d] = floatBitsToUint(%s);' % (wi, ref))
                else:
                    out.append('  w[%d] = uint(%s);' % (wi, ref))
                wi += 1
        out.append('}')
        return out


# ------------------------------------------------------------------------------------------------
# Scenes: one draw per program; each draw's patch covers a region of the image, one row per point

LEVEL = 3
IMG_W = 1024
REGION_H = 16


def layout_regions(programs):
    """(x0, y0) per program in window coordinates (y up), regions of 2 * words pixels by 16."""
    pos = []
    x = y = 0
    for p in programs:
        w = 2 * len(p.words)
        if x + w > IMG_W:
            x = 0
            y += REGION_H
        pos.append((x, y))
        x += w
    height = y + REGION_H
    return pos, height


VERT = """#version 450 core
in float in_dummy;
void main() { gl_Position = vec4(in_dummy); }
"""

TESC = """#version 450 core
layout(vertices = 1) out;
void main() {
  gl_TessLevelOuter = float[4](3.0, 3.0, 3.0, 3.0);
  gl_TessLevelInner = float[2](3.0, 3.0);
}
"""


def nvec4(nw):
    return (nw + 3) // 4


def tese_text(p, x0, y0, img_h):
    nw = len(p.words)
    out = ['#version 450 core', 'layout(quads, equal_spacing, ccw) in;',
           'flat out int o_point;', 'flat out uvec4 o_w[%d];' % nvec4(nw)]
    out += p.body_glsl()
    out += ['void main() {',
            '  int p = int(gl_TessCoord.x * 3.0 + 0.5) + 4 * int(gl_TessCoord.y * 3.0 + 0.5);',
            '  uint w[%d];' % nw, '  dt_compute(p, w);',
            # keeps both uniform arrays active whatever the program reads (tessref refuses values
            # for an inactive uniform; a driver ignores them)
            '  o_point = p + (floatBitsToInt(u_f[0]) & u_i[0] & 0);',
            '  for (int k = 0; k < %d; ++k) o_w[k >> 2][k & 3] = w[k];' % nw,
            # the patch covers pixels [x0, x0 + 2 nw) x [y0, y0 + 16) of the window
            '  vec2 pix = vec2(%d.0, %d.0) + gl_TessCoord.xy * vec2(%d.0, 16.0);' % (x0, y0, 2 * nw),
            '  gl_Position = vec4(pix / vec2(%d.0, %d.0) * 2.0 - 1.0, 0.0, 1.0);' % (IMG_W, img_h),
            '}']
    return '\n'.join(out) + '\n'


def frag_text(p, x0, y0):
    nw = len(p.words)
    out = ['#version 450 core', 'layout(location = 0) out vec4 o_color;']
    out += p.body_glsl()
    out += ['void main() {',
            '  int col = int(gl_FragCoord.x) - %d;' % x0,
            '  int row = int(gl_FragCoord.y) - %d;' % y0,
            '  uint w[%d];' % nw, '  dt_compute(clamp(row, 0, 15), w);',
            '  uint bits = w[clamp(col >> 1, 0, %d)] >> (16 * (col & 1));' % (nw - 1),
            '  o_color = vec4(float(bits & 255u), float((bits >> 8) & 255u), 0.0, 255.0) / 255.0;',
            '}']
    return '\n'.join(out) + '\n'


def write_scene(folder, programs):
    os.makedirs(folder, exist_ok=True)
    pos, height = layout_regions(programs)
    with open(os.path.join(folder, 'dt.vert'), 'w') as f:
        f.write(VERT)
    with open(os.path.join(folder, 'dt.tesc'), 'w') as f:
        f.write(TESC)
    draws = []
    for k, (p, (x0, y0)) in enumerate(zip(programs, pos)):
        te = 'p%d.tese' % k
        fr = 'p%d.frag' % k
        with open(os.path.join(folder, te), 'w') as f:
            f.write(tese_text(p, x0, y0, height))
        with open(os.path.join(folder, fr), 'w') as f:
            f.write(frag_text(p, x0, y0))
        draws.append({
            'shaders': {'vertex': 'dt.vert', 'tess_control': 'dt.tesc', 'tess_evaluation': te,
                        'fragment': fr,
                        'uniforms': p.uniforms()},
            'mode': 'GL_PATCHES', 'patch_vertices': 1,
            'vertex_arrays': {'in_dummy': {'buffer': 'dummy', 'size': 1, 'type': 'GL_FLOAT'}},
            'first': 0, 'count': 1,
            'transform_feedback': {'varyings': ['o_point'] + ['o_w[%d]' % i for i in range(nvec4(len(p.words)))]},
        })
    scene = {
        'description': 'glsl-differential: one generated program per draw (scripts/glsl-differential.py)',
        'image': {'width': IMG_W, 'height': height},
        'background': [0.0, 0.0, 0.0, 1.0],
        'shaders': {'program': 'custom', 'vertex': 'dt.vert', 'fragment': 'p0.frag',
                    'scene_uniforms': False},
        'buffers': {'dummy': {'type': 'GL_FLOAT', 'data': [0.0]}},
        'draws': draws,
    }
    with open(os.path.join(folder, 'scene.json'), 'w') as f:
        json.dump(scene, f, indent=1)
    return pos, height


# ------------------------------------------------------------------------------------------------
# Reading results

def read_png_rgb(path):
    """An 8-bit RGB or RGBA PNG as rows of bytes (top row first), 3 bytes a pixel."""
    data = open(path, 'rb').read()
    if data[:8] != b'\x89PNG\r\n\x1a\n':
        raise ValueError('%s: not a PNG' % path)
    pos = 8
    idat = b''
    while pos < len(data):
        ln, typ = struct.unpack('>I4s', data[pos:pos + 8])
        chunk = data[pos + 8:pos + 8 + ln]
        if typ == b'IHDR':
            w, h, depth, ctype = struct.unpack('>IIBB', chunk[:10])
        elif typ == b'IDAT':
            idat += chunk
        pos += 12 + ln
    if depth != 8 or ctype not in (2, 6):
        raise ValueError('%s: an 8-bit RGB or RGBA PNG was expected' % path)
    bpp = 3 if ctype == 2 else 4
    raw = zlib.decompress(idat)
    stride = w * bpp
    rows = []
    prev = bytearray(stride)
    i = 0
    for _ in range(h):
        ft = raw[i]
        line = bytearray(raw[i + 1:i + 1 + stride])
        i += 1 + stride
        if ft == 1:
            for x in range(bpp, stride):
                line[x] = (line[x] + line[x - bpp]) & 255
        elif ft == 2:
            for x in range(stride):
                line[x] = (line[x] + prev[x]) & 255
        elif ft == 3:
            for x in range(stride):
                left = line[x - bpp] if x >= bpp else 0
                line[x] = (line[x] + ((left + prev[x]) >> 1)) & 255
        elif ft == 4:
            for x in range(stride):
                a = line[x - bpp] if x >= bpp else 0
                b = prev[x]
                c = prev[x - bpp] if x >= bpp else 0
                pp = a + b - c
                pa, pb, pc = abs(pp - a), abs(pp - b), abs(pp - c)
                pr = a if pa <= pb and pa <= pc else (b if pb <= pc else c)
                line[x] = (line[x] + pr) & 255
        rows.append(line)
        prev = line
    if bpp == 4:
        rows = [bytearray(b for k, b in enumerate(r) if k % 4 != 3) for r in rows]
    return w, h, rows


def read_feedback(path, nw):
    """point -> tuple of words; all records of one point must agree (else 'inconsistent')."""
    data = open(path, 'rb').read()
    rec = 4 * (1 + 4 * nvec4(nw))
    out = {}
    bad = False
    for off in range(0, len(data) - rec + 1, rec):
        vals = struct.unpack('<i%dI' % (4 * nvec4(nw)), data[off:off + rec])
        p = vals[0]
        w = vals[1:1 + nw]
        if p in out and out[p] != w:
            bad = True
        out[p] = w
    return out, bad


def read_fragment(rows, img_h, x0, y0, nw, npoints):
    """point -> words, from the region of the image (window y up, PNG rows top down)."""
    out = {}
    for p in range(npoints):
        row = rows[img_h - 1 - (y0 + p)]
        words = []
        for k in range(nw):
            x = x0 + 2 * k
            lo = row[3 * x] | (row[3 * x + 1] << 8)
            hi = row[3 * x + 3] | (row[3 * x + 4] << 8)
            words.append(lo | (hi << 16))
        out[p] = tuple(words)
    return out


# ------------------------------------------------------------------------------------------------
# Checking

class Stats:
    def __init__(self):
        self.programs = 0
        self.values = 0
        self.identical = 0
        self.within = 0          # different bits, both within the tolerance
        self.beyond = 0          # a side beyond the tolerance: a disagreement
        self.unchecked = 0       # a side's own inputs left the operation's domain
        self.by_op = {}          # op -> [values, differing, beyond, max ulp between sides]
        self.failures = []       # (program id, stage, point, statement, detail)
        self.side_beyond = {'tessref': 0, 'llvmpipe': 0}
        self.stage_values = {'tes': 0, 'frag': 0}
        self.structural = []

    def op(self, name):
        # values, differing, beyond, max ULP apart from identical inputs, differing from identical
        # inputs, largest error / tolerance on tessref's side, on llvmpipe's side
        return self.by_op.setdefault(name, [0, 0, 0, 0, 0, 0.0, 0.0])


def env_from_words(prog, point, words):
    """The side's values of every variable at one point: inputs from the scene, results read back."""
    env = {}
    for k in range(prog.nf):
        env['f%d' % k] = [EF(prog.fin[point * prog.nf + k])]
    for k in range(prog.ni):
        env['i%d' % k] = [prog.iin[point * prog.ni + k]]
    wi = 0
    for st in prog.stmts:
        n = ncomp(st.typ)
        comps = []
        for c in range(n):
            b = words[wi]
            wi += 1
            if is_float(st.typ):
                comps.append(EF(bits_f32(b)))
            else:
                comps.append(i32(b) if st.typ == 'int' else u32(b))
        env[st.name] = comps
    return env


def accepts(alts, got_bits, typ):
    """(within tolerance, error in units of the tolerance) for one component."""
    if not is_float(typ):
        want = alts[0]
        return (u32(want) == got_bits, 0.0 if u32(want) == got_bits else float('inf'))
    y = bits_f32(got_bits)
    if y != y or abs(y) == float('inf'):
        return False, float('inf')
    best = float('inf')
    for a in alts:
        tol = a.e * (1 + 1e-9) + abs(a.x) * 2.0 ** -50 + 1e-300
        # GLSL 4.50 4.7.1: denormals may be flushed to zero
        if abs(a.x) < MIN_NORMAL * 1.0001 and abs(y) < MIN_NORMAL:
            return True, 0.0
        ratio = abs(y - a.x) / tol if tol > 0 else (0.0 if y == a.x else float('inf'))
        best = min(best, ratio)
    return best <= 1.0, best


def check_program(prog, sides, stats, stage):
    """sides: {'tessref': {point: words}, 'llvmpipe': {point: words}}; counts every value."""
    nw = len(prog.words)
    problems = []
    for p in range(prog.npoints):
        t = sides['tessref'].get(p)
        l = sides['llvmpipe'].get(p)
        if t is None or l is None:
            problems.append((stage, p, None, 'point %d missing on %s' % (p, 'tessref' if t is None else 'llvmpipe')))
            continue
        envs = {'tessref': env_from_words(prog, p, t), 'llvmpipe': env_from_words(prog, p, l)}
        wi = 0
        for si, st in enumerate(prog.stmts):
            n = ncomp(st.typ)
            verdict = {}
            for side in ('tessref', 'llvmpipe'):
                try:
                    verdict[side] = st.fn(envs[side])
                except (Domain, OverflowError, ValueError, ZeroDivisionError):
                    verdict[side] = None
            for c in range(n):
                bt = t[wi + c]
                bl = l[wi + c]
                stats.values += 1
                stats.stage_values[stage] += 1
                o = stats.op(st.op)
                o[0] += 1
                same_inputs = all([x.x if isinstance(x, EF) else x for x in envs['tessref'][r]] ==
                                  [x.x if isinstance(x, EF) else x for x in envs['llvmpipe'][r]]
                                  for r in st.reads)
                if bt != bl:
                    o[1] += 1
                    if same_inputs:
                        o[4] += 1
                        o[3] = max(o[3], ulp_distance(bt, bl) if is_float(st.typ) else 1 << 40)
                else:
                    stats.identical += 1
                bad = []
                for side, bits in (('tessref', bt), ('llvmpipe', bl)):
                    alts = verdict[side]
                    if alts is None:
                        continue
                    ok, ratio = accepts(alts[c], bits, st.typ)
                    k = 5 if side == 'tessref' else 6
                    if is_float(st.typ) and ratio > o[k]:
                        o[k] = ratio
                    if not ok:
                        a0 = alts[c][0]
                        want = ('%.9g (bound %.3g)' % (a0.x, a0.e)) if isinstance(a0, EF) else str(a0)
                        got = repr(bits_f32(bits)) if is_float(st.typ) else str(i32(bits) if st.typ == 'int' else bits)
                        bad.append((side, 'got %s, exact %s, %.3g x the tolerance' % (got, want, ratio)))
                if verdict['tessref'] is None or verdict['llvmpipe'] is None:
                    if bt != bl and not bad:
                        stats.unchecked += 1
                if bad:
                    stats.beyond += 1
                    o[2] += 1
                    for side, _ in bad:
                        stats.side_beyond[side] += 1
                    problems.append((stage, p, si, '; '.join('%s %s' % b for b in bad) +
                                     ' [component %d; tessref %08x, llvmpipe %08x]' % (c, bt, bl)))
                elif bt != bl:
                    stats.within += 1
            wi += n
    return problems


# ------------------------------------------------------------------------------------------------
# Running a batch

def run(cmd, cwd=None):
    r = subprocess.run(cmd, cwd=cwd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    return r.returncode, r.stdout


def make_programs(seed, first, count, nstmts_range, max_words):
    _TLS.generating = True
    out = []
    for pid in range(first, first + count):
        rng = random.Random('%d:%d' % (seed, pid))
        p = Program(rng, pid)
        p.generate(rng.randint(*nstmts_range), max_words)
        if not p.words:
            p.generate(4, max_words)
        out.append(p)
    _TLS.generating = False
    return out


def run_batch(args, batch_index, programs):
    """Writes the scene of one batch and runs both sides on it, one after the other.
    Returns (workdir, pos, height, [(exit status, output) of tessref, of the capture])."""
    workdir = tempfile.mkdtemp(prefix='dt-%d-' % batch_index, dir=args.workdir)
    pos, height = write_scene(workdir, programs)
    scene = os.path.join(workdir, 'scene.json')
    cap = os.path.join(workdir, 'capture')
    tprefix = os.path.join(workdir, 'tessref')
    cmds = [
        [args.tessref, 'render', scene, '-o', tprefix + '.png', '--threads', '1',
         '--transform-feedback', tprefix],
        [args.tessref, 'capture', scene, '--out', cap],
    ]
    return workdir, pos, height, [run(c) for c in cmds]


def keep(args, workdir, programs, problems_by_pid):
    if not args.keep_failures:
        return
    for p in programs:
        if p.pid not in problems_by_pid:
            continue
        d = os.path.join(args.keep_failures, 'program-%d' % p.pid)
        os.makedirs(d, exist_ok=True)
        sub = write_scene(d, [p])
        with open(os.path.join(d, 'problems.txt'), 'w') as f:
            for stage, point, si, text in problems_by_pid[p.pid]:
                where = 'statement %s (%s)' % (p.stmts[si].name, p.stmts[si].op) if si is not None else ''
                f.write('%s point %d %s: %s\n' % (stage, point, where, text))


def plant(prog, words):
    """A planted fault (--plant): tessref's first exact-or-correctly-rounded float result at point
    0 moved by one ULP, or its first integer result by one; the check must report it."""
    w = list(words)
    wi = 0
    for st in prog.stmts:
        n = ncomp(st.typ)
        if st.op in ('+', '-', '*', 'constructor', 'swizzle', 'abs', 'floor', 'negate', 'float(int)') or not is_float(st.typ):
            w[wi] = u32(w[wi] + 1)
            prog.planted = st.op
            return tuple(w)
        wi += n
    return tuple(w)


def check_batch(args, batch_index, programs, ran, stats):
    workdir, pos, height, res = ran
    (rc_t, out_t), (rc_l, out_l) = res
    problems_by_pid = {}
    if rc_t != 0 or rc_l != 0:
        msg = 'batch %d: tessref render exit %d, capture exit %d\n%s\n%s' % (
            batch_index, rc_t, rc_l, out_t[-3000:], out_l[-3000:])
        stats.structural.append(msg)
        for p in programs:
            problems_by_pid[p.pid] = [('run', 0, None, 'the batch did not run')]
        keep(args, workdir, programs, problems_by_pid)
        if not args.keep_work:
            shutil.rmtree(workdir, ignore_errors=True)
        return problems_by_pid
    _, _, rows_t = read_png_rgb(os.path.join(workdir, 'tessref.png'))
    _, _, rows_l = read_png_rgb(os.path.join(workdir, 'capture', 'color.png'))
    for d, (p, (x0, y0)) in enumerate(zip(programs, pos)):
        nw = len(p.words)
        tf_t, bad_t = read_feedback(os.path.join(workdir, 'tessref.draw%d.buffer0.bin' % d), nw)
        tf_l, bad_l = read_feedback(os.path.join(workdir, 'capture', 'feedback.draw%d.buffer0.bin' % d), nw)
        probs = []
        if bad_t or bad_l:
            probs.append(('tes', 0, None, 'transform feedback records of one point differ (%s)' %
                          ('tessref' if bad_t else 'llvmpipe')))
        if args.plant and 0 in tf_t:
            tf_t[0] = plant(p, tf_t[0])
        probs += check_program(p, {'tessref': tf_t, 'llvmpipe': tf_l}, stats, 'tes')
        fr_t = read_fragment(rows_t, height, x0, y0, nw, p.npoints)
        fr_l = read_fragment(rows_l, height, x0, y0, nw, p.npoints)
        probs += check_program(p, {'tessref': fr_t, 'llvmpipe': fr_l}, stats, 'frag')
        stats.programs += 1
        if probs:
            problems_by_pid[p.pid] = probs
    keep(args, workdir, programs, problems_by_pid)
    if not args.keep_work:
        shutil.rmtree(workdir, ignore_errors=True)
    return problems_by_pid


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument('--count', type=int, default=200, help='programs to generate and run')
    ap.add_argument('--seed', type=int, default=20250, help="the generator's seed")
    ap.add_argument('--first', type=int, default=0, help='the first program number (programs are numbered from the seed)')
    ap.add_argument('--batch', type=int, default=50, help='programs per scene (one GL context per scene)')
    ap.add_argument('--jobs', type=int, default=2, help='1: run tessref and the capture one after the other')
    ap.add_argument('--tessref', default=None, help='the tessref command (default: build/cli/tessref)')
    ap.add_argument('--keep-failures', default=None, metavar='DIR',
                    help='write each failing program as a scene of one draw, with its problems, here')
    ap.add_argument('--plant', action='store_true',
                    help="self-check: move one of tessref's exact results by one ULP (or 1) per program; "
                         'every program must then fail')
    ap.add_argument('--keep-work', action='store_true', help='keep the batch folders (in --workdir)')
    ap.add_argument('--workdir', default=None, help='where the batch folders go (default: a temporary folder)')
    ap.add_argument('--max-words', type=int, default=48, help='values a program records (at most 63)')
    ap.add_argument('--statements', default='6,24', help='statements per program, MIN,MAX')
    ap.add_argument('--print-program', type=int, default=None, metavar='ID',
                    help='print program ID of the seed (its evaluation shader) and exit')
    args = ap.parse_args()
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    if args.tessref is None:
        args.tessref = os.path.join(root, 'build', 'cli', 'tessref')
    lo, hi = (int(x) for x in args.statements.split(','))
    if args.print_program is not None:
        p = make_programs(args.seed, args.print_program, 1, (lo, hi), args.max_words)[0]
        sys.stdout.write(tese_text(p, 0, 0, REGION_H))
        return 0
    own_workdir = args.workdir is None
    if own_workdir:
        args.workdir = tempfile.mkdtemp(prefix='glsl-differential-')
    os.makedirs(args.workdir, exist_ok=True)
    stats = Stats()
    start = time.time()
    failed_programs = {}
    done = 0
    nbatches = (args.count + args.batch - 1) // args.batch
    batches = []
    for b in range(nbatches):
        first = args.first + b * args.batch
        n = min(args.batch, args.first + args.count - first)
        batches.append((b, first, n))

    def work(item):
        b, first, n = item
        progs = make_programs(args.seed, first, n, (lo, hi), args.max_words)
        return b, progs, run_batch(args, b, progs)

    with ThreadPoolExecutor(max(1, args.jobs)) as ex:
        futures = [ex.submit(work, item) for item in batches]
        for fut in futures:
            b, progs, ran = fut.result()
            failed_programs.update(check_batch(args, b, progs, ran, stats))
            done += len(progs)
            el = time.time() - start
            sys.stderr.write('\r%d/%d programs, %d values, %d disagreements, %.0f s (%.1f programs/s)   ' % (
                done, args.count, stats.values, stats.beyond, el, done / el))
            sys.stderr.flush()
    sys.stderr.write('\n')
    el = time.time() - start
    if own_workdir and not args.keep_work:
        shutil.rmtree(args.workdir, ignore_errors=True)
    # summary
    print('glsl-differential: seed %d, programs %d..%d (%d), %.1f s' % (
        args.seed, args.first, args.first + args.count - 1, stats.programs, el))
    print('values compared: %d (evaluation shader %d, fragment shader %d)' % (
        stats.values, stats.stage_values['tes'], stats.stage_values['frag']))
    print('  identical bits: %d; different within GLSL precision: %d; beyond it (disagreements): %d'
          % (stats.identical, stats.within, stats.beyond))
    print('  beyond on tessref\'s side: %d, on llvmpipe\'s side: %d; differing values a side could '
          'not be checked on (its inputs outside the domain): %d' % (
              stats.side_beyond['tessref'], stats.side_beyond['llvmpipe'], stats.unchecked))
    print('per operation: values; values whose bits differ (all, and of those from identical inputs); '
          'disagreements;\nthe largest ULP distance between the sides from identical inputs; the largest '
          'error of each side\nagainst the exact result of its own inputs, in units of the tolerance '
          '(1: at the limit)')
    print('%-28s %9s %8s %8s %7s %9s %8s %8s' % ('operation', 'values', 'differ', 'same-in', 'beyond',
                                                  'max ULP', 'tessref', 'llvmpipe'))
    for name in sorted(stats.by_op):
        v, d, bz, mu, ds, rt, rl = stats.by_op[name]
        mus = '-' if ds == 0 else ('int' if mu >= 1 << 40 else str(mu))
        print('%-28s %9d %8d %8d %7d %9s %8.3f %8.3f' % (name, v, d, ds, bz, mus, rt, rl))
    for s in stats.structural:
        print('ERROR: ' + s)
    shown = 0
    for pid in sorted(failed_programs):
        for stage, point, si, text in failed_programs[pid]:
            if shown < 20:
                print('FAIL program %d, %s, point %d%s: %s' % (
                    pid, stage, point, '' if si is None else ', statement %d' % si, text))
            shown += 1
    if shown > 20:
        print('... %d more' % (shown - 20))
    ok = stats.beyond == 0 and not stats.structural and not failed_programs
    print('result: %s' % ('PASS' if ok else 'FAIL (%d programs)' % len(failed_programs)))
    return 0 if ok else 1


if __name__ == '__main__':
    sys.exit(main())
