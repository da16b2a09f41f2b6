# Sourced by the scripts in docs/bench: sets `cpu` (the model name, with the family and model
# numbers where /proc/cpuinfo has them), `features` (`AVX2 AVX-512`,
# `AVX2` or `no AVX2`) and `host_line` (one line naming both, the thread count, the commit and the
# date), and prints that line. On a CPU driver the vector units decide the speed (issue 23), so
# every figure these scripts print is preceded by it. Mesa's GALLIUM_OVERRIDE_CPU_CAPS,
# LP_NATIVE_VECTOR_WIDTH and GALLIVM_PERF, which change what or how lavapipe compiles, and rtc's
# RTC_UNIFORM_TABLES, which changes the kernels it gets, are named when set. (When LP_NATIVE_VECTOR_WIDTH is not set, `rtc` sets 128 for itself on lavapipe before
# Mesa 26; the adapter line the scripts print names the width lavapipe used: "128 bits".)
cpu=$(grep -m1 'model name' /proc/cpuinfo 2>/dev/null | cut -d: -f2- | sed 's/^ *//')
cpu=${cpu:-$(uname -m)}
# The family and model numbers tell apart what a VM's model name hides (`AMD EPYC`: family 25 is
# Zen 3 or Zen 4, 26 Zen 5), as rtc's own `host:` line does.
family=$(grep -m1 '^cpu family' /proc/cpuinfo 2>/dev/null | cut -d: -f2- | tr -d ' \t' || true)
model=$(grep -m1 -E '^model[[:space:]]*:' /proc/cpuinfo 2>/dev/null | cut -d: -f2- | tr -d ' \t' || true)
[[ -n $family && -n $model ]] && cpu+=", family $family model $model"
flags=$(grep -m1 '^flags' /proc/cpuinfo 2>/dev/null || true)
features=AVX2
[[ $flags == *avx512f* ]] && features="AVX2 AVX-512"
[[ $flags == *avx2* ]] || features="no AVX2"
host_line="cpu: $cpu ($features, $(nproc) threads)"
# (`host_var`, not `var`: the scripts that source this file have variables of their own, and
# driver_ab.sh's `var` names the variable it measures.)
for host_var in GALLIUM_OVERRIDE_CPU_CAPS LP_NATIVE_VECTOR_WIDTH GALLIVM_PERF RTC_UNIFORM_TABLES; do
    [[ -n ${!host_var:-} ]] && host_line+="; $host_var=${!host_var}"
done
unset host_var
host_line+="; commit $(git rev-parse --short HEAD 2>/dev/null || echo unknown), $(date -u +%Y-%m-%d)"
echo "$host_line"
