//! The wavefront execution model's stage kernels and the layout of its per-path state.
//!
//! Beside the megakernel (`render`: one invocation traces a pixel's samples to completion), a scene
//! can be compiled to six stage kernels (`stdlib/kernel/wavefront.rt`) that a host runs in rounds
//! over one tile of pixels, each pixel owning one *path slot* in the `paths` binding:
//!
//! | stage | entry | does | traversal code |
//! |---|---|---|---|
//! | count | `wf_count` | counts the running slots of each of `COMPACT_BLOCKS` blocks of the last round's list (of the tile in its first round) | none |
//! | compact | `wf_compact` | lists those slots in slot order in the other of two lists, their count and the listed stages' indirect dispatch | none |
//! | trace | `wf_trace` | for a slot starting a sample, first its camera ray (seeds, calls the camera); the closest hit of the slot's pending ray (with `@intersection` and `@any_hit`); for media, first the medium the camera ray starts in or a refracted ray enters when the shade stage could not tell it | one copy, and the medium probe for media |
//! | shade | `wf_shade` | one shading step: miss, `@secondary_rays`, `@closest_hit`, `@medium`, `@light`; the next ray or the finished sample | one copy for its shadow rays, or none in a scene with a shadow stage |
//! | shadow | `wf_shadow` | the shadow queries the last shading step recorded (only in a scene whose shade stage replays them) | one copy |
//! | finish | `wf_finish` | adds the pass's samples to `accum` and resets the slot (not after a round over a tile the host listed whose shade stage did it) | none |
//!
//! A round is count, compact, trace, shade, and, when the scene has a shadow stage, shadow,
//! shade. A slot starts a sample (`STATUS_CAMERA`: a zeroed record, and after each sample of a
//! pass of several but the last) in the trace stage, which makes the camera ray and traces it at
//! once: a camera stage of its own cost a dispatch a round and the ray's store and load, more
//! than the camera's code in the trace kernel. The count and compact stages run as a few
//! workgroups, one invocation a block of entries, over the list the round before made (over the
//! tile in a tile's first round: the running set only shrinks within a tile, as a slot becomes
//! idle in the shade stage and running again in the finish stage), and list the slots still
//! running in the other of two lists: a round's listing costs its running paths, not the tile
//! (glass_mirror's 62 rounds list 12.6 % of the slots they would scan). The other stages of the
//! round run over that *list*, through an indirect dispatch of as many workgroups as it needs:
//! once some paths have ended (Russian roulette, misses), the lanes of those stages still all hold
//! a running path, and a round costs what its running paths cost. The host runs count and compact
//! again at the end of each round, for the next (`runtime`'s `gpu::dispatch::rounds`), so the
//! count it reads says whether another round is needed and no round runs only to find nothing.
//! The listed stages take the list in runs of 8 workgroups, the runs permuted (the compact stage
//! stores each entry at its place, `list_place`), so that each thread of a CPU driver, which
//! takes a contiguous range of a dispatch's workgroups, gets paths from all over the tile. The
//! finish stage runs over the tile. When every path ends in a tile's first round (no secondary
//! rays, no shadow stage, one sample a pass: a shading step always ends its sample), the count
//! and compact stages would list every slot and then find none: the host instead stores the
//! tile's slot count, its workgroups and [`LIST_TILE`] in the tail, and the listed stages take
//! the tile's slots in runs permuted by a multiplication (`tile_place`), one round a tile with no
//! listing and no read-back. There the shade stage also does the finish stage's work as each
//! sample ends (`sample_done`, lowered to `wf_sample_accumulate`: the sample to `accum`, the
//! slot's first chunk reset), and no finish stage runs, where `accum` fits within the stage's
//! [`MAX_STORAGE_BUFFERS`] (`CompiledScene::shade_accumulates`; not in a scene whose shade
//! stage reads textures or vertex attributes beside the traversal's buffers, such as the thesis
//! scene).
//!
//! Shadow rays ([`super::ShadowRays`], chosen by [`super::lower_shade_stage`]): where the shading
//! step's `shadow(…)` calls, with every call inlined as a driver inlines them, reach the traversal
//! at most [`MAX_SHADE_TRAVERSALS`] times in a render of at most [`FAST_COMPILE_MAX_SAMPLES`]
//! samples (whose time is mostly its compile), or [`MAX_SHADE_TRAVERSALS_FAST_FRAMES`] times in a
//! larger one, the shade stage traces them where they are made, as the megakernel does (the same
//! random numbers too), and the scene has no shadow stage: a step runs once. Otherwise each call
//! site would be one more copy of the traversal to compile, and `shadow(…)` in the shade stage
//! does not trace: it is *replayed* (`shadow_replay` in `stdlib/kernel/trace.rt`). The first run
//! of a shading step records each query it makes and answers "unoccluded"; the recorded queries
//! are traced; the step then runs again from the same saved state (same random numbers), and each
//! query that equals a recorded one bit for bit gets its traced answer. Only a step whose every
//! query was answered commits its results, so the outcome is the megakernel's. A step whose later
//! queries depend on the answers of earlier ones records the changed ones and goes round again.
//! Who traces the recorded queries:
//! - in the small render, the shadow stage, and the step runs again in the round's second shade
//!   dispatch: the shade stage holds no traversal.
//! - in the larger one, the shade stage itself ([`SHADE_REPLAY_ROOT`]): its one call of the step
//!   and one traversal, in a loop. When every answer is the "unoccluded" the run assumed, the
//!   run's results are what a replay would compute, and the step commits at once; only a step
//!   with an occluded query runs again. The scene has no shadow stage.
//!
//! Termination: the compact stage stores the count of running slots into the word after the
//! tile's records, `PATH_WORDS * path_slots` (the first word of the *tail*, [`tail_bytes`]); the
//! host ends the tile's rounds when it reads 0 after one, and zeroes the word before a tile's
//! first round, which the count stage reads as "list the tile". Rays are counted per slot
//! (`PATH_RAYS`) and added to `COUNTER_RAYS` once a pixel by the finish stage: one atomic a
//! pixel, as in the megakernel, instead of one per stage (atomics on one address from every lane
//! serialise the CPU's threads).
//!
//! Guarantees: the layout below is the one source of the path record's word offsets (they reach
//! the kernel as `rtc:config` constants, [`config_constants`]); every stage kernel is a separate
//! module with its own bindings, each at most WebGPU's default 8 storage buffers (tested for every
//! example); `paths` holds `PATH_WORDS` words per slot, a whole number of 4-word chunks stored
//! chunk-major (chunk `c` of slot `i` is element `c * path_slots + i` of an array of `vec4u`, so
//! the lanes of a SIMD batch read neighbouring elements), and every field of three words or more
//! starts a chunk: a vector is one load, where lavapipe before Mesa 26 pays per load.

use crate::link::KernelConfig;

/// The stage kernels, in the order a round runs them (the shade stage runs twice a round when
/// the shadow stage is there) and their kernel functions in `stdlib/kernel/wavefront.rt`. A scene
/// whose shade stage traces its shadow rays has every stage but [`Stage::Shadow`]
/// ([`stages`]).
pub const STAGES: [Stage; 6] = [
    Stage::Count,
    Stage::Compact,
    Stage::Trace,
    Stage::Shade,
    Stage::Shadow,
    Stage::Finish,
];

/// The stage kernels of a scene, in [`STAGES`] order: all of them with a shadow stage, else all
/// but [`Stage::Shadow`].
pub fn stages(shadow_stage: bool) -> impl Iterator<Item = Stage> {
    STAGES
        .into_iter()
        .filter(move |&s| shadow_stage || s != Stage::Shadow)
}

/// The most copies of the traversal ([`TRAVERSAL_FN`]) the shade stage may hold, every call
/// inlined, to trace its shadow rays where they are made in a render whose time is its compile
/// ([`super::ShadowRays::AutoFastCompile`]); with more, the shadow stage traces them. One: the
/// shadow stage's own copy moves into it, so the scene's compile stays what it was (the stage
/// kernels of thesis_scene and cornell_path compile in about the same time,
/// docs/bench/compile.md), while a second copy would cost a traversal's compile (gltf_scene's
/// shade stage, two copies: 1.6 s against 0.68 s with lavapipe's quick JIT).
pub const MAX_SHADE_TRAVERSALS: u64 = 1;

/// The most copies of the traversal the shade stage may hold to trace its shadow rays where they
/// are made in a render whose time is its frames ([`super::ShadowRays::AutoFastFrames`]); with
/// more, it replays them around its one traversal ([`SHADE_REPLAY_ROOT`]). Three, the most any
/// example has (fog): on fog, gltf_scene, pbr_path and shading, tracing in place gave frames 0.70
/// to 0.93 of the replay's, and a compile within the spread of the replay's, whose loop around
/// the step costs the driver too (docs/bench/lavapipe.md,
/// "Shadow rays replayed in the shade stage (2026-12-06)").
pub const MAX_SHADE_TRAVERSALS_FAST_FRAMES: u64 = 3;

/// The most samples of a render for which [`super::ShadowRays::Auto`] means
/// [`super::ShadowRays::AutoFastCompile`], beyond which it means
/// [`super::ShadowRays::AutoFastFrames`]: 128 K (e.g. 362 x 362 at 1 spp), the most lavapipe's
/// quick JIT compiles the stage kernels for (`rtc_runtime::gpu::QUICK_JIT_MAX_SAMPLES`). Up to
/// there a render's time is mostly its compile, which a traversal in the shade stage makes 0.3 to
/// 1.1 s longer than the shadow stage's (quick JIT, Mesa 25); beyond, the frames count
/// (docs/bench/lavapipe.md, "Shadow rays replayed in the shade stage (2026-12-06)").
pub const FAST_COMPILE_MAX_SAMPLES: u64 = 1 << 17;

/// The kernel function of the shade stage that replays its shadow rays within the stage
/// ([`super::ShadowRays::Replay`]): the entry point is still [`Stage::Shade`]'s.
pub const SHADE_REPLAY_ROOT: &str = "wf_shade_replay_invocation";

/// The most samples of a render whose shade stage leaves the accumulation of a tile the host
/// listed to the finish stage (beyond it, `CompiledScene::shade_accumulates` where it can): 16 K,
/// the bound below which `rtc render` on a CPU adapter picks the wavefront model for its faster
/// compile (`rtc_runtime::gpu::WAVEFRONT_PREVIEW_MAX_SAMPLES`). The accumulation made the shade
/// stage's cold compile 36 to 50 ms longer (cornell_box, lambert_only; Mesa 25.0.7, quick JIT,
/// medians of 8) to save a finish dispatch of under a millisecond at that size
/// (docs/bench/lavapipe.md, "The finish stage's work in the shade stage of a listed tile (2026-12-06, late)").
pub const SHADE_ACCUMULATES_MIN_SAMPLES: u64 = 1 << 14;

/// Storage buffers a stage kernel may bind: WebGPU's default `maxStorageBuffersPerShaderStage`.
pub const MAX_STORAGE_BUFFERS: usize = 8;

/// The storage buffers among `bindings` (every binding but the uniform ones).
pub fn storage_buffers(bindings: &[&crate::abi::BindingDesc]) -> usize {
    bindings
        .iter()
        .filter(|b| b.kind != crate::back::ResourceKind::Uniform)
        .count()
}

/// The kernel function that traverses the scene, in `stdlib/kernel/trace.rt`.
pub const TRAVERSAL_FN: &str = "intersect_scene";

/// One stage kernel of the wavefront model.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Stage {
    /// Running slots per block of the tile.
    Count,
    /// The list of running slots and the listed stages' dispatch.
    Compact,
    /// Closest hits of pending rays (a new sample's camera ray first).
    Trace,
    /// One shading step per path.
    Shade,
    /// Recorded shadow queries.
    Shadow,
    /// Accumulation and slot reset.
    Finish,
}

impl Stage {
    /// The entry point's name (also the stage's name in summaries and outputs).
    pub fn entry(self) -> &'static str {
        match self {
            Stage::Count => "wf_count",
            Stage::Compact => "wf_compact",
            Stage::Trace => "wf_trace",
            Stage::Shade => "wf_shade",
            Stage::Shadow => "wf_shadow",
            Stage::Finish => "wf_finish",
        }
    }

    /// The kernel function the entry point calls with the invocation's id.
    pub fn root(self) -> &'static str {
        match self {
            Stage::Count => "wf_count_invocation",
            Stage::Compact => "wf_compact_invocation",
            Stage::Trace => "wf_trace_invocation",
            Stage::Shade => "wf_shade_invocation",
            Stage::Shadow => "wf_shadow_invocation",
            Stage::Finish => "wf_finish_invocation",
        }
    }

    /// How the host dispatches the stage: over the tile, as a row of [`COMPACT_WORKGROUPS`]
    /// workgroups, or over the list of running slots.
    pub fn dispatch(self) -> StageDispatch {
        match self {
            Stage::Finish => StageDispatch::Tile,
            Stage::Count | Stage::Compact => StageDispatch::Blocks,
            Stage::Trace | Stage::Shade | Stage::Shadow => StageDispatch::Listed,
        }
    }

    /// The stage whose entry point is `entry`.
    pub fn from_entry(entry: &str) -> Option<Stage> {
        STAGES.into_iter().find(|s| s.entry() == entry)
    }
}

/// How a stage kernel is dispatched ([`Stage::dispatch`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum StageDispatch {
    /// One invocation per pixel of the tile (workgroups cover the tile).
    Tile,
    /// A row of [`COMPACT_WORKGROUPS`] workgroups, one invocation per block of slots
    /// ([`COMPACT_BLOCKS`]).
    Blocks,
    /// Indirectly, from the workgroup count the compact stage stored at
    /// [`TAIL_DISPATCH_OFFSET`] bytes into the tail: one invocation per listed slot, the `n`-th
    /// at `gid = ((n / 64) * 8 + n % 8, (n / 8) % 8)` (workgroups of 8 x 8 in a row).
    Listed,
}

/// Workgroups of the count and compact stages: a few, so every thread of a CPU driver counts.
pub const COMPACT_WORKGROUPS: u32 = 4;
/// Blocks of slots the count and compact stages split a tile into: one invocation each,
/// [`COMPACT_WORKGROUPS`] workgroups of the stage kernels' 8 x 8.
pub const COMPACT_BLOCKS: u32 =
    COMPACT_WORKGROUPS * super::RENDER_WORKGROUP[0] * super::RENDER_WORKGROUP[1];
/// Chunks of the tail before the lists: the running count and the indirect dispatch (one chunk),
/// then the blocks' counts (a chunk each, in its first word; the first block's chunk also holds,
/// in its other words, which list the listed stages read and the count stage's copy of the length
/// and list it read, for the compact stage).
pub const TAIL_HEAD_CHUNKS: u32 = 1 + COMPACT_BLOCKS;
/// Byte offset, from the start of the tail, of the listed stages' indirect dispatch arguments
/// (`x, y, z` workgroups, after the running count).
pub const TAIL_DISPATCH_OFFSET: u64 = 4;
/// Word of the tail's second chunk (the first block count's) that says which list the listed
/// stages read: 0 or 1, which the compact stage stores, or [`LIST_TILE`].
pub const LIST_SELECTOR: u32 = 1;
/// [`LIST_SELECTOR`]'s value for the tile itself: the listed stages' invocation `n` takes the
/// `n`-th place of the tile's slots in `tile_place`'s order. The host stores it, with the tail's
/// first chunk (the tile's slots and their workgroups), for a pass whose every path ends in the
/// tile's first round (no secondary rays, no shadow stage, one sample a pass): the count and
/// compact stages would list every slot, and find none after it.
pub const LIST_TILE: u32 = 2;
/// Byte offset, from the start of the tail, of [`LIST_SELECTOR`]'s word.
pub const TAIL_SELECTOR_OFFSET: u64 = (CHUNK_WORDS as u64 + LIST_SELECTOR as u64) * 4;

/// Bytes of the tail of `paths` after a tile's records (`slots` records): the running count and
/// the indirect dispatch (one chunk), the blocks' counts, then the two lists, a chunk a slot
/// (list 0 in its first word, list 1 in its second). Each count and each entry of a list takes a
/// word of a chunk no other invocation of the same stage writes: one store with no other
/// invocation's word beside it, and one load, where a word packed four to a chunk needs a branch
/// for each place it can have (literal component indices, as `paths.rt` uses; the list's word is
/// one branch, the same for every invocation of a dispatch).
pub fn tail_bytes(slots: u32) -> u64 {
    (u64::from(TAIL_HEAD_CHUNKS) + u64::from(slots)) * u64::from(CHUNK_WORDS) * 4
}

/// Shadow queries one shading step records (a step's further queries are answered "unoccluded"
/// and counted in `COUNTER_SHADOW_OVERFLOW`). At most 32: the answers are bits of one word.
pub const SHADOW_QUERIES: u32 = 8;
const _: () = assert!(SHADOW_QUERIES <= 32);
/// Words of a ray in the path record: origin, tmin, dir, tmax (a chunk each), then depth, kind,
/// medium.
pub const RAY_WORDS: u32 = 11;
/// Words of a traversal candidate: t, slot, primitive, uv, normal (two chunks).
pub const CANDIDATE_WORDS: u32 = 8;
/// Words of a recorded shadow query: origin and tmax, then dir and a word left unused (two chunks).
pub const QUERY_WORDS: u32 = 8;
/// Words of one chunk of `paths`: the stages load and store a record's vectors a chunk at a time.
pub const CHUNK_WORDS: u32 = 4;

/// Lays out `fields` (name, words) one after another, a field of three words or more (or of none,
/// whose offset is then where the next chunk starts) starting a new chunk (so its vectors load as whole chunks): each name with its word offset, and the total
/// rounded up to whole chunks.
fn layout(fields: &[(&'static str, u32)]) -> (Vec<(&'static str, u32)>, u32) {
    let mut at: u32 = 0;
    let offsets = fields
        .iter()
        .map(|&(name, words)| {
            if words >= 3 || words == 0 {
                at = at.next_multiple_of(CHUNK_WORDS);
            }
            let offset = at;
            at += words;
            (name, offset)
        })
        .collect();
    (offsets, at.next_multiple_of(CHUNK_WORDS))
}

/// The word offsets of one secondary-ray frame and its size: ray, candidate, the hit's position
/// and position error (one chunk), geometric normal and the spawned-ray count (one chunk), the
/// children's weighted sum and the next one to launch (one chunk), then `max_spawn` directions and
/// `max_spawn` weights (a chunk each). The stage reads and writes a frame whole.
fn frame_layout(c: &KernelConfig) -> (Vec<(&'static str, u32)>, u32) {
    layout(&[
        ("FRAME_RAY", RAY_WORDS),
        ("FRAME_CANDIDATE", CANDIDATE_WORDS),
        ("FRAME_POSITION", 3),
        ("FRAME_ERROR", 1),
        ("FRAME_NORMAL", 3),
        ("FRAME_COUNT", 1),
        ("FRAME_SUM", 3),
        ("FRAME_NEXT", 1),
        ("FRAME_DIRS", CHUNK_WORDS * c.max_spawn),
        ("FRAME_WEIGHTS", CHUNK_WORDS * c.max_spawn),
    ])
}

/// Words of one secondary-ray frame ([`frame_layout`]).
pub fn frame_words(c: &KernelConfig) -> u32 {
    frame_layout(c).1
}

/// The named word offsets of the path record and of a stack frame in it, and their sizes, as
/// `(name, value)`: the constants `rtc:config` declares for `stdlib/kernel/`.
pub fn config_constants(c: &KernelConfig) -> Vec<(&'static str, u32)> {
    let (frame, frame_words) = frame_layout(c);
    // A path loop carries its throughput and radiance so far (`PATH_BETA`, `PATH_RADIANCE`,
    // 3 words each) instead of a stack of frames.
    let (frames, carried) = if c.path_loop {
        (0, 3)
    } else if c.has_secondary_rays {
        (c.stack_size * frame_words, 0)
    } else {
        (0, 0)
    };
    let absorb = if c.has_absorb { SHADOW_QUERIES } else { 0 };
    // Chunks: status, sample, rng and ray count (what the traversal stages touch besides their
    // rays); the sum and the bad-sample count (written together); the stack depth and the shadow
    // queries' three counters (the shading step's); then the vectors, chunk-aligned. A stage
    // loads whole 64-byte cache lines, four slots' chunks, so the fewer chunks a stage touches
    // the better: each costs a line per four slots where a word-major word costs one per 16.
    let (mut out, path_words) = layout(&[
        ("PATH_STATUS", 1),
        ("PATH_SAMPLE", 1),
        ("PATH_RNG", 1),
        ("PATH_RAYS", 1),
        ("PATH_SUM", 3),
        ("PATH_BAD", 1),
        ("PATH_DEPTH", 1),
        ("PATH_SQ_RESOLVED", 1),
        ("PATH_SQ_RECORDED", 1),
        ("PATH_SQ_BITS", 1),
        ("PATH_RAY", RAY_WORDS),
        ("PATH_CANDIDATE", CANDIDATE_WORDS),
        ("PATH_SQ", SHADOW_QUERIES * QUERY_WORDS),
        // With `absorb`, each query's start medium and its answer's transmittance.
        ("PATH_SQ_MEDIUM", absorb),
        ("PATH_SQ_T", absorb),
        ("PATH_BETA", carried),
        ("PATH_RADIANCE", carried),
        ("PATH_FRAMES", frames),
    ]);
    out.push(("PATH_WORDS", path_words));
    out.extend(frame);
    out.push(("FRAME_WORDS", frame_words));
    out.push(("SHADOW_QUERIES", SHADOW_QUERIES));
    out.push(("RAY_WORDS", RAY_WORDS));
    out.push(("CANDIDATE_WORDS", CANDIDATE_WORDS));
    out.push(("QUERY_WORDS", QUERY_WORDS));
    out.push(("CHUNK_WORDS", CHUNK_WORDS));
    out.push(("COMPACT_BLOCKS", COMPACT_BLOCKS));
    out.push(("TAIL_HEAD_CHUNKS", TAIL_HEAD_CHUNKS));
    out.push(("LIST_SELECTOR", LIST_SELECTOR));
    out.push(("LIST_TILE", LIST_TILE));
    out
}

/// Words of one path slot for a kernel configured by `c`.
pub fn path_words(c: &KernelConfig) -> u32 {
    config_constants(c)
        .iter()
        .find(|(n, _)| *n == "PATH_WORDS")
        .map_or(0, |&(_, v)| v)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::back::ResourceKind;
    use crate::driver::Options;
    use crate::kernel::{compile_scene_with, ExecModel, KernelOptions};
    use crate::link::LinkOptions;

    /// Every example's stage kernels: lowered and validated, each within WebGPU's default 8
    /// storage buffers; only the trace and shadow stages (and a shade stage that traces its shadow
    /// rays) read BVH nodes; only the finish stage declares `accum`, and the shade stage of a scene
    /// whose samples all end in their first shading step. Where the shadow rays are traced,
    /// from the copies of the traversal the shade stage holds tracing them where they are made
    /// (counted here on the shade stage lowered that way): there, for a render of at most
    /// `FAST_COMPILE_MAX_SAMPLES` samples, with at most `MAX_SHADE_TRAVERSALS` copies, else in
    /// the shadow stage; for a larger one with at most `MAX_SHADE_TRAVERSALS_FAST_FRAMES`, else
    /// replayed in the shade stage (`SHADE_REPLAY_ROOT`). The examples' own sizes take both ways
    /// of a small render, and the first of a large one (no example has more than three copies);
    /// a small render of each takes its way too.
    #[test]
    fn every_example_has_stage_kernels_within_the_default_limits() {
        let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../examples");
        let mut names: Vec<_> = std::fs::read_dir(&root)
            .unwrap()
            .filter_map(|e| {
                let p = e.ok()?.path().join("scene.rt");
                p.exists().then_some(p)
            })
            .collect();
        names.sort();
        assert!(names.len() >= 10, "{names:?}");
        // Examples tracing their shadow rays in the shade stage at their own sizes, and in the
        // shadow stage in a small render.
        let mut placements = [0u32; 2];
        let mut one_step_examples: Vec<(String, bool)> = Vec::new();
        for path in names {
            let compiled = compile_scene_with(
                std::slice::from_ref(&path),
                None,
                &Options::default(),
                &LinkOptions::default(),
                &KernelOptions {
                    exec: Some(ExecModel::Wavefront),
                    ..KernelOptions::default()
                },
            )
            .unwrap_or_else(|f| {
                panic!(
                    "{}: {}",
                    path.display(),
                    crate::diag::render_human(&f.checked.sources, &f.diagnostics, false)
                )
            });
            let stages = compiled.stages.as_ref().expect("stage kernels");
            let shadow_stage = compiled.has_shadow_stage();
            assert_eq!(
                stages.iter().map(|s| s.stage).collect::<Vec<_>>(),
                super::stages(shadow_stage).collect::<Vec<_>>()
            );
            let (inline, _, traces) = crate::kernel::lower_shade_stage(
                &compiled.checked,
                &compiled.linked,
                crate::kernel::ShadowRays::Shade,
                false,
            )
            .expect("the shade stage, tracing");
            assert!(traces);
            let copies =
                crate::kernel::weight::inlined_copies(&inline, Stage::Shade.entry(), TRAVERSAL_FN)
                    .expect("the entry point");
            let program = compiled.checked.program.as_ref().expect("the program");
            let own = program.scenes[compiled.scene].settings;
            let small = u64::from(own.width * own.height * own.samples) <= FAST_COMPILE_MAX_SAMPLES;
            let most = if small {
                MAX_SHADE_TRAVERSALS
            } else {
                MAX_SHADE_TRAVERSALS_FAST_FRAMES
            };
            let in_place = copies <= most;
            assert!(
                copies <= MAX_SHADE_TRAVERSALS_FAST_FRAMES,
                "{}",
                path.display()
            );
            assert_eq!(
                shadow_stage,
                !in_place,
                "{}: {copies} traversals",
                path.display()
            );
            assert!(
                !compiled.replays_in_shade_stage(),
                "{}: {copies} traversals",
                path.display()
            );
            let (_, _, traces) = crate::kernel::lower_shade_stage(
                &compiled.checked,
                &compiled.linked,
                crate::kernel::ShadowRays::AutoFastCompile,
                false,
            )
            .expect("the shade stage for a small render");
            assert_eq!(
                traces,
                copies <= MAX_SHADE_TRAVERSALS,
                "{}: {copies} traversals",
                path.display()
            );
            placements[0] += u32::from(!shadow_stage);
            placements[1] += u32::from(!traces);
            for s in stages {
                let names: Vec<&str> = s.bindings.iter().map(|b| b.name).collect();
                let storage = s
                    .bindings
                    .iter()
                    .filter(|b| b.kind != ResourceKind::Uniform)
                    .count();
                assert!(
                    storage <= 8,
                    "{}: {:?} has {storage} storage buffers: {names:?}",
                    path.display(),
                    s.stage
                );
                assert!(names.contains(&"paths"), "{:?}: {names:?}", s.stage);
                let nodes = names.contains(&"nodes");
                match s.stage {
                    Stage::Trace | Stage::Shadow => assert!(nodes),
                    Stage::Count | Stage::Compact => {
                        assert!(!nodes);
                        assert_eq!(storage, 1, "{:?}: {names:?}", s.stage);
                    }
                    // A shade stage holds a traversal only to trace shadow rays.
                    Stage::Shade => {
                        assert!(!nodes || !shadow_stage, "{}: {:?}", path.display(), s.stage)
                    }
                    Stage::Finish => assert!(!nodes),
                }
                // A shade stage whose samples all end in their first step accumulates them in a
                // listed tile (`wf_sample_accumulate`) where `accum` fits its bindings.
                let one_step = !compiled.linked.config.has_secondary_rays && !shadow_stage;
                if s.stage == Stage::Shade {
                    assert_eq!(names.contains(&"accum"), compiled.shade_accumulates());
                    assert!(
                        !compiled.shade_accumulates() || one_step,
                        "{}",
                        path.display()
                    );
                    if one_step {
                        let name = path.parent().and_then(|p| p.file_name());
                        let name = name.map(|n| n.to_string_lossy().into_owned());
                        one_step_examples
                            .push((name.unwrap_or_default(), compiled.shade_accumulates()));
                    }
                } else {
                    assert_eq!(names.contains(&"accum"), s.stage == Stage::Finish);
                }
                assert_eq!(s.module.entry_points.len(), 1);
                assert_eq!(s.module.entry_points[0].name, s.stage.entry());
            }
        }
        // The examples whose samples end in their first shading step, and whether their shade
        // stage accumulates: not where its storage buffers (with `counters`, for the ray count)
        // leave no room for `accum` (gltf_scene's, thesis_scene's and three_spheres', which read
        // textures or vertex attributes beside the traversal's buffers).
        let expected: Vec<(String, bool)> = [
            ("cameras", true),
            ("cornell_box", true),
            ("gltf_scene", false),
            ("lambert_only", true),
            ("lights", true),
            ("thesis_scene", false),
            ("three_spheres", false),
        ]
        .map(|(n, a)| (n.to_string(), a))
        .to_vec();
        assert_eq!(one_step_examples, expected);
        assert!(
            placements.iter().all(|&n| n > 0),
            "examples tracing their shadow rays in the shade stage at their own sizes, and in the \
             shadow stage in a small render: {placements:?}"
        );
    }

    /// `ShadowRays::Auto` weighs the render's samples: the shading example (two traversals' worth
    /// of shadow calls) traces its shadow rays in the shade stage, where they are made, at its own
    /// 480 x 200 at 4 spp, and leaves them to the shadow stage at 64 x 48, whether `--size` and
    /// `--spp` both give the render or `--spp` alone shrinks the scene's own size below the bound.
    #[test]
    fn the_render_size_decides_where_shadow_rays_are_traced() {
        let path =
            std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../examples/shading/scene.rt");
        let stages = |render_size: Option<[u32; 2]>, render_spp: Option<u32>| {
            let compiled = compile_scene_with(
                std::slice::from_ref(&path),
                None,
                &Options::default(),
                &LinkOptions::default(),
                &KernelOptions {
                    exec: Some(ExecModel::Wavefront),
                    render_size,
                    render_spp,
                    ..KernelOptions::default()
                },
            )
            .unwrap_or_else(|_| panic!("{} compiles", path.display()));
            assert!(compiled.stages.is_some(), "stage kernels");
            (
                compiled.has_shadow_stage(),
                compiled.replays_in_shade_stage(),
            )
        };
        // 480 x 200 x 4 = 384 K samples; 64 x 48 x 1 and 480 x 200 x 1 = 96 K are within the bound.
        assert_eq!(stages(None, None), (false, false));
        assert_eq!(stages(Some([64, 48]), Some(1)), (true, false));
        assert_eq!(stages(None, Some(1)), (true, false));
        assert_eq!(stages(Some([1920, 1080]), None), (false, false));
    }

    #[test]
    fn the_layout_is_in_chunks_and_counts_frames_only_with_secondary_rays() {
        let mut c = KernelConfig::unspecialised();
        c.has_absorb = false;
        let with = path_words(&c);
        c.has_secondary_rays = false;
        let without = path_words(&c);
        assert_eq!(with - without, c.stack_size * frame_words(&c));
        // Three chunks of single words and the sum, then the ray (padded to 12 words), the
        // candidate and the queries.
        assert_eq!(
            without,
            12 + 12 + CANDIDATE_WORDS + SHADOW_QUERIES * QUERY_WORDS
        );
        // A path loop carries a throughput and a radiance (a chunk each) instead of frames.
        c.has_secondary_rays = true;
        c.path_loop = true;
        assert_eq!(path_words(&c), without + 8);
        // `absorb` records each query's start medium and transmittance.
        c.has_absorb = true;
        assert_eq!(path_words(&c), without + 8 + 2 * SHADOW_QUERIES);
        // Every vector starts a chunk, and records and frames are whole chunks.
        for config in [c, KernelConfig::unspecialised()] {
            let constants = config_constants(&config);
            let get = |name: &str| constants.iter().find(|(n, _)| *n == name).unwrap().1;
            for name in [
                "PATH_SUM",
                "PATH_RAY",
                "PATH_CANDIDATE",
                "PATH_SQ",
                "PATH_BETA",
                "PATH_RADIANCE",
                "PATH_FRAMES",
                "PATH_WORDS",
                "FRAME_CANDIDATE",
                "FRAME_POSITION",
                "FRAME_NORMAL",
                "FRAME_SUM",
                "FRAME_DIRS",
                "FRAME_WEIGHTS",
                "FRAME_WORDS",
                "QUERY_WORDS",
            ] {
                assert_eq!(get(name) % CHUNK_WORDS, 0, "{name}");
            }
            // Words the stages read alone, at the offsets `paths.rt` assumes within their chunk.
            assert_eq!(get("FRAME_ERROR"), get("FRAME_POSITION") + 3);
            assert_eq!(get("FRAME_COUNT"), get("FRAME_NORMAL") + 3);
            assert_eq!(get("FRAME_NEXT"), get("FRAME_SUM") + 3);
            assert_eq!(get("PATH_BAD"), get("PATH_SUM") + 3);
            // The finish stage resets the first chunk with one store.
            let first = ["PATH_STATUS", "PATH_SAMPLE", "PATH_RNG", "PATH_RAYS"].map(get);
            assert_eq!(first, [0, 1, 2, 3]);
        }
        for stage in STAGES {
            assert_eq!(Stage::from_entry(stage.entry()), Some(stage));
        }
    }
}
