#!/usr/bin/env bash
# Runs a command with the current release of Mesa's lavapipe instead of the system's.
#
#   bash docs/bench/current_lavapipe.sh target/release/rtc render examples/thesis_scene/scene.rt -o out.png
#   bash docs/bench/current_lavapipe.sh        (no command: prints the unpacked Mesa's version)
#   CARGO_TARGET_X86_64_UNKNOWN_LINUX_GNU_RUNNER="bash $PWD/docs/bench/current_lavapipe.sh" cargo test ...
#
# (As a cargo runner, the test binaries run on it; processes they start, such as `rtc` itself, do
# not.)
#
# Debian 12 packages Mesa 25.0 at best (bookworm-backports). lavapipe's shader compiler got much
# faster at what ray tracing kernels do in later releases (storage-buffer loads under divergent
# control flow; see docs/bench/lavapipe.md), and those releases are built for
# newer C libraries. This script unpacks Debian 13 ("trixie") backports' mesa-vulkan-drivers and
# the trixie libraries it needs (C library and loader included, about 60 packages) into a folder,
# without root and without touching the system, then runs the command under trixie's dynamic
# loader with only that lavapipe visible to the Vulkan loader. The binaries built on Debian 12 run
# unchanged on the newer C library.
#
# The folder is `RTC_MESA_ROOT`, by default ~/.cache/rtc/lavapipe-trixie-backports; it is made on
# the first run (about 40 s and 200 MB) and reused. Only deb.debian.org is needed.
set -euo pipefail
root=${RTC_MESA_ROOT:-${XDG_CACHE_HOME:-$HOME/.cache}/rtc/lavapipe-trixie-backports}
sysroot=$root/sysroot
if [[ ! -e $root/ready ]]; then
    rm -rf "$root"
    mkdir -p "$root/apt/lists/partial" "$root/apt/archives/partial" "$root/apt/etc/parts" "$sysroot"
    : >"$root/apt/status"
    cat >"$root/apt/etc/sources.list" <<'EOF'
deb http://deb.debian.org/debian trixie main
deb http://deb.debian.org/debian trixie-backports main
EOF
    apt_opts=(
        -o "Dir::Etc::SourceList=$root/apt/etc/sources.list"
        -o "Dir::Etc::SourceParts=$root/apt/etc/parts"
        -o "Dir::Etc::Preferences=/nonexistent"
        -o "Dir::Etc::PreferencesParts=$root/apt/etc/parts"
        -o "Dir::State=$root/apt"
        -o "Dir::State::Lists=$root/apt/lists"
        -o "Dir::State::status=$root/apt/status"
        -o "Dir::Cache=$root/apt"
        -o "Dir::Cache::Archives=$root/apt/archives"
        -o "APT::Architecture=amd64"
        -o "APT::Architectures=amd64"
        -o "Debug::NoLocking=1"
        # Mirrors and proxies may serve a Release file past its Valid-Until date.
        -o "Acquire::Check-Valid-Until=false"
    )
    echo "current_lavapipe: unpacking Debian trixie-backports' lavapipe into $root" >&2
    apt-get "${apt_opts[@]}" -q update >/dev/null
    # `-t trixie-backports`: the backported Mesa and whatever newer libraries it needs.
    apt-get "${apt_opts[@]}" -q -y --no-install-recommends --download-only -t trixie-backports install \
        mesa-vulkan-drivers libvulkan1 >/dev/null
    for deb in "$root"/apt/archives/*.deb; do
        dpkg-deb -x "$deb" "$sysroot"
    done
    rm -rf "$root/apt/archives" "$root/apt/lists"
    # The Vulkan loader may only find this lavapipe: its manifest, with an absolute path.
    lib=$sysroot/usr/lib/x86_64-linux-gnu
    printf '{ "file_format_version": "1.0.1", "ICD": { "library_path": "%s", "api_version": "1.3.0" } }\n' \
        "$lib/libvulkan_lvp.so" >"$root/lvp_icd.json"
    ls "$sysroot"/usr/share/doc/mesa-vulkan-drivers >/dev/null
    touch "$root/ready"
fi
if [[ $# -eq 0 ]]; then
    gzip -dc "$sysroot/usr/share/doc/mesa-vulkan-drivers/changelog.Debian.gz" | sed -n 1p
    exit 0
fi
lib=$sysroot/usr/lib/x86_64-linux-gnu
export VK_DRIVER_FILES=$root/lvp_icd.json VK_ICD_FILENAMES=$root/lvp_icd.json
export XDG_RUNTIME_DIR=${XDG_RUNTIME_DIR:-$(mktemp -d)}
exec "$sysroot/usr/lib64/ld-linux-x86-64.so.2" --library-path "$lib" "$@"
