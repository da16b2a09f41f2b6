//! Rounds of stage kernels over each tile: the wavefront model's dispatch.
//!
//! For each tile, a round is one command buffer. Its kernels ([`RoundKernels::round`]) are
//! dispatched in order (same tile parameters, each with its own bind group): over the tile, as a
//! row of workgroups, or indirectly from workgroup counts an earlier kernel of the round stored in
//! the flag's buffer, copied before the first of them ([`RoundDispatch`]). The round's direct
//! kernels before its first indirect one (those that list the running paths and store the
//! *running* word) run once more at its end, for the next round: the word is then copied to a
//! mapped buffer and read, and at 0 the tile's paths are done, without a round that runs only to
//! find nothing. A tile's first round starts with those kernels too. The finish kernel then runs
//! once over the tile. When every path ends in a tile's first round
//! ([`RoundKernels::tile_list`]), the host stores the word and the workgroup counts for the whole
//! tile itself, and the tile's one round runs without the listing kernels and without a
//! read-back, and without the finish kernel where the round's kernels do its work.
//! Tiles run one after the other, so one tile's path state is all the state buffer has to hold.
//!
//! With [`RoundKernels::timed`], every dispatch of a round is submitted and waited for alone and
//! timed, and the report sums each kernel's milliseconds ([`RoundsReport::stage_ms`]): a profile
//! of where a wavefront frame goes, slower than the plain dispatch by the waits, with the same
//! results.
//!
//! Invariants: a tile never runs more than the caller's `max_rounds` rounds (more is an error,
//! [`DispatchError::TooManyRounds`], not a hang); every wgpu call runs in an error scope.

use super::*;

/// How a kernel of a round is dispatched.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum RoundDispatch {
    /// Workgroups covering the tile.
    Tile,
    /// A row of this many workgroups.
    Row(u32),
    /// Indirectly: the `x, y, z` workgroup counts at this byte offset (a multiple of 4) of the
    /// flag's buffer ([`RoundKernels::flag_binding`]), written by an earlier kernel of the round
    /// (not by an indirect one). They are copied to a buffer of their own first (a buffer bound
    /// for storage cannot be read as indirect arguments by the same dispatch), once for a run of
    /// indirect dispatches from the same offset.
    Indirect(u64),
}

/// The kernels of a wavefront dispatch.
pub struct RoundKernels<'a> {
    /// The kernels of one round, dispatched in this order and way (a kernel may appear twice).
    pub round: Vec<(&'a Kernel, RoundDispatch)>,
    /// The kernel run once over a tile after its last round.
    pub finish: &'a Kernel,
    /// Every path ends in a tile's first round: the host lists the tile itself ([`TileList`]),
    /// and the round runs without its leading direct kernels and without a read-back (and, when
    /// its kernels accumulate the samples, without the finish kernel after it).
    pub tile_list: Option<TileList>,
    /// The binding of the buffer holding the *running* word: zeroed before a tile's first round,
    /// set by the round's leading direct kernels to the number of paths the (next) round runs
    /// (a round without such kernels: zeroed before each round and set by its kernels), non-zero
    /// while some path still runs (and holding the indirect dispatches' workgroup counts).
    pub flag_binding: u32,
    /// The byte offset of that word (a multiple of 4).
    pub flag_offset: u64,
    /// Rounds a tile may take before the dispatch gives up.
    pub max_rounds: u32,
    /// Submit, wait for and time each dispatch alone ([`RoundsReport::stage_ms`]).
    pub timed: bool,
}

/// How the host lists a tile for a round that is its last ([`RoundKernels::tile_list`]): it
/// stores the tile's slot count as the *running* word, the indirect dispatches' workgroups after
/// it (`x` to cover the slots, `y = z = 1`), and `selector` at `selector_offset`, the word that
/// tells the indirect kernels to take the tile's slots rather than a list. With `accumulates`,
/// the round's kernels also do the finish kernel's work (each path's sample goes to the image,
/// each slot starts again), and the finish kernel does not run after it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct TileList {
    /// Byte offset of the selector's word in the flag's buffer (a multiple of 4).
    pub selector_offset: u64,
    /// The selector's value for the tile.
    pub selector: u32,
    /// Invocations a workgroup of the indirect kernels.
    pub group: u32,
    /// The round's kernels accumulate the tile's samples and start its slots again.
    pub accumulates: bool,
}

/// What a wavefront dispatch did.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct RoundsReport {
    /// Tiles, batches (one per tile) and times, as for a plain dispatch.
    pub dispatch: DispatchReport,
    /// Rounds run over all tiles (a tile's last round is the one after which nothing runs).
    pub rounds: u64,
    /// The *running* words of the rounds, summed: the paths the rounds ran (for the wavefront
    /// model, the slots its listed stages ran over).
    pub running: u64,
    /// The tile's pixels summed over the same rounds: what the rounds would run over with every
    /// slot in every round (`running / tile_slots` is the fraction of lanes that held a path).
    pub tile_slots: u64,
    /// With [`RoundKernels::timed`]: milliseconds of each kernel (by label, in round order, the
    /// finish kernel last) over all tiles, each dispatch timed alone; empty otherwise.
    pub stage_ms: Vec<(String, f64)>,
}

/// Adds `ms` to `label`'s entry of `stage_ms` (a new entry goes last).
pub(crate) fn add_stage_ms(stage_ms: &mut Vec<(String, f64)>, label: &str, ms: f64) {
    match stage_ms.iter_mut().find(|(l, _)| l == label) {
        Some((_, total)) => *total += ms,
        None => stage_ms.push((label.to_string(), ms)),
    }
}

impl TileDispatcher {
    /// Runs `kernels` over a `width × height` image, tile after tile: rounds until no path is
    /// running, then the finish kernel. `frame` goes to [`TileParams::frame`]; `progress(done,
    /// total)` is called before the first tile and after each.
    pub fn dispatch_rounds(
        &mut self,
        gpu: &Gpu,
        kernels: &RoundKernels<'_>,
        buffers: &BufferSet,
        [width, height]: [u32; 2],
        frame: u32,
        progress: &mut dyn FnMut(u32, u32),
    ) -> Result<RoundsReport, DispatchError> {
        let config = self.config;
        check_config(&config)?;
        let mut all: Vec<&Kernel> = kernels.round.iter().map(|(k, _)| *k).collect();
        all.push(kernels.finish);
        let mut tile_binding = None;
        for k in &all {
            match k.tile_binding() {
                Some(b) if tile_binding.is_none_or(|t| t == b) => tile_binding = Some(b),
                _ => {
                    return Err(DispatchError::NoTileBinding {
                        kernel: k.label().to_string(),
                    })
                }
            }
        }
        let Some(tile_binding) = tile_binding else {
            return Ok(RoundsReport::default());
        };
        let tiles = plan_tiles(width, height, config.tile_width, config.tile_height, frame);
        let total = u32::try_from(tiles.len()).unwrap_or(u32::MAX);
        let mut report = RoundsReport {
            dispatch: DispatchReport {
                tiles: total,
                ..DispatchReport::default()
            },
            rounds: 0,
            running: 0,
            tile_slots: 0,
            stage_ms: Vec::new(),
        };
        let timed = kernels.timed;
        progress(0, total);
        if tiles.is_empty() {
            return Ok(report);
        }
        for k in &all {
            check_workgroups(gpu, k, &config)?;
        }
        let (params, stride) = self.upload_tiles(gpu, &tiles)?;
        let groups: Vec<wgpu::BindGroup> = all
            .iter()
            .map(|k| bind_group(gpu, k, buffers, Some((tile_binding, tile_resource(params)))))
            .collect::<Result<_, _>>()?;
        let flag = buffers
            .buffer(kernels.flag_binding)
            .ok_or_else(|| BufferError::Missing {
                set: buffers.label().to_string(),
                binding: kernels.flag_binding,
            })?;
        let flag_offset = kernels.flag_offset;
        let (staging, error) = gpu.scoped(|| {
            gpu.device().create_buffer(&wgpu::BufferDescriptor {
                label: Some("rtc running paths"),
                size: 8,
                usage: wgpu::BufferUsages::MAP_READ | wgpu::BufferUsages::COPY_DST,
                mapped_at_creation: false,
            })
        });
        wgpu_result("read-back allocation", error)?;
        let (indirect, error) = gpu.scoped(|| {
            gpu.device().create_buffer(&wgpu::BufferDescriptor {
                label: Some("rtc round workgroups"),
                size: 12,
                usage: wgpu::BufferUsages::INDIRECT | wgpu::BufferUsages::COPY_DST,
                mapped_at_creation: false,
            })
        });
        wgpu_result("read-back allocation", error)?;
        let runs = round_runs(&kernels.round);
        // The leading direct runs before the first indirect one: the ones that list the running
        // slots (none in a round without indirect dispatches).
        let head = runs
            .iter()
            .position(|r| matches!(r, Run::Indirect { .. }))
            .unwrap_or(0);

        // A tile's first round and its later ones as (index into its `runs`, where in the
        // read-back buffer to copy the word after it): the first starts with the head and reads
        // its word (the round's list length) at 0; each ends with the head and reads the next
        // round's at 4.
        let orders: [Vec<(usize, Option<u64>)>; 2] = [true, false].map(|first| {
            let head_runs =
                |read: u64| (0..head).map(move |r| (r, (r + 1 == head).then_some(read)));
            let mut order: Vec<(usize, Option<u64>)> = Vec::new();
            if first {
                order.extend(head_runs(0));
            }
            order.extend((head..runs.len()).map(|r| (r, None)));
            order.extend(head_runs(4));
            if let Some(last) = order.last_mut() {
                last.1 = Some(4);
            }
            order
        });

        // A round over the tile listed by the host: the first round's runs after the leading
        // direct ones, nothing read back.
        let tile_order: Vec<(usize, Option<u64>)> = (head..runs.len()).map(|r| (r, None)).collect();

        report.dispatch.flush_ms = flush_uploads(gpu)?;

        let start = Instant::now();
        let finish_group = groups.len() - 1;
        for (done, tile) in tiles.iter().enumerate() {
            let slots = u64::from(tile.extent[0]) * u64::from(tile.extent[1]);
            // Fits: the buffer size was checked against u32 offsets in params_buffer.
            let offset = (u64::from(tile.tile_index) * stride) as u32;
            let dispatch_kernel = |pass: &mut wgpu::ComputePass<'_>,
                                   k: &Kernel,
                                   how: RoundDispatch,
                                   group: &wgpu::BindGroup| {
                pass.set_pipeline(k.pipeline());
                pass.set_bind_group(0, group, &[offset]);
                match how {
                    RoundDispatch::Tile => {
                        let [x, y] = tile_workgroups(k, tile);
                        pass.dispatch_workgroups(x, y, 1);
                    }
                    RoundDispatch::Row(n) => pass.dispatch_workgroups(n, 1, 1),
                    RoundDispatch::Indirect(_) => pass.dispatch_workgroups_indirect(&indirect, 0),
                }
            };
            // The round's kernel at `at`.
            let dispatch = |pass: &mut wgpu::ComputePass<'_>, at: usize| {
                let (k, how) = kernels.round[at];
                dispatch_kernel(pass, k, how, &groups[at]);
            };
            let round = "rtc wavefront round";
            // A round's runs, then its leading direct runs (count, compact) again for the next
            // round, so the word read after a round is the next round's list length and a
            // tile's rounds end without one that finds nothing. The tile's first round starts
            // with the leading runs too, and also reads the word they store (its list's length).
            let mut listed: Option<u32> = None;
            let mut finished = false;
            if let Some(t) = kernels.tile_list {
                let slots = u32::try_from(slots).unwrap_or(u32::MAX);
                let mut words = Vec::with_capacity(16);
                for w in [slots, slots.div_ceil(t.group.max(1)), 1, 1] {
                    words.extend_from_slice(&w.to_le_bytes());
                }
                let ((), error) = gpu.scoped(|| {
                    gpu.queue().write_buffer(flag, flag_offset, &words);
                    gpu.queue()
                        .write_buffer(flag, t.selector_offset, &t.selector.to_le_bytes());
                });
                wgpu_result("tile list upload", error)?;
            }
            for _ in 0..kernels.max_rounds {
                let first = listed.is_none();
                let order = if kernels.tile_list.is_some() {
                    &tile_order
                } else {
                    &orders[usize::from(!first)]
                };
                let read = |e: &mut wgpu::CommandEncoder, to: u64| {
                    e.copy_buffer_to_buffer(flag, flag_offset, &staging, to, Some(4));
                };
                let copy = |e: &mut wgpu::CommandEncoder, at: u64| {
                    e.copy_buffer_to_buffer(flag, at, &indirect, 0, Some(12));
                };
                // Without leading direct kernels, the word is the round's own, zeroed before it.
                let zero = kernels.tile_list.is_none() && (first || head == 0);
                if timed {
                    // The profile: each dispatch alone, waited for.
                    if zero {
                        submit(gpu, round, "wavefront round", |e| {
                            e.clear_buffer(flag, flag_offset, Some(4))
                        })?;
                    }
                    let mut timed_one = |at: usize, counts: Option<u64>| {
                        let label = kernels.round[at].0.label();
                        let begin = Instant::now();
                        submit(gpu, label, "wavefront round", |e| {
                            if let Some(counts) = counts {
                                copy(e, counts);
                            }
                            dispatch(&mut begin_pass(e, label), at)
                        })?;
                        wait(gpu)?;
                        add_stage_ms(&mut report.stage_ms, label, elapsed_ms(begin));
                        Ok::<(), DispatchError>(())
                    };
                    for &(r, to) in order {
                        match &runs[r] {
                            Run::Direct(at) => timed_one(*at, None)?,
                            Run::Indirect { counts, kernels } => {
                                for (i, &at) in kernels.iter().enumerate() {
                                    timed_one(at, (i == 0).then_some(*counts))?;
                                }
                            }
                        }
                        if let Some(to) = to {
                            submit(gpu, round, "wavefront round", |e| read(e, to))?;
                        }
                    }
                } else {
                    submit(gpu, round, "wavefront round", |e| {
                        if zero {
                            e.clear_buffer(flag, flag_offset, Some(4));
                        }
                        // One pass for each run of direct dispatches and each run of indirect
                        // ones, whose counts are copied before its pass.
                        let mut pass: Option<wgpu::ComputePass<'static>> = None;
                        for &(r, to) in order {
                            match &runs[r] {
                                Run::Direct(at) => {
                                    let pass = pass.get_or_insert_with(|| {
                                        begin_pass(e, round).forget_lifetime()
                                    });
                                    dispatch(pass, *at);
                                }
                                Run::Indirect { counts, kernels } => {
                                    drop(pass.take());
                                    copy(e, *counts);
                                    let mut listed_pass = begin_pass(e, round);
                                    for &at in kernels {
                                        dispatch(&mut listed_pass, at);
                                    }
                                }
                            }
                            if let Some(to) = to {
                                drop(pass.take());
                                read(e, to);
                            }
                        }
                    })?;
                }
                report.rounds += 1;
                report.tile_slots += slots;
                if kernels.tile_list.is_some() {
                    report.running += slots;
                    finished = true;
                    break;
                }
                let [this, next] = map_read(gpu, &staging, 8, |bytes| {
                    let word = |i: usize| {
                        u32::from_le_bytes([bytes[i], bytes[i + 1], bytes[i + 2], bytes[i + 3]])
                    };
                    [word(0), word(4)]
                })?;
                // The paths this round ran: its list's length, or, without leading direct
                // kernels, the word its kernels stored.
                let ran = if head == 0 {
                    next
                } else {
                    listed.unwrap_or(this)
                };
                report.running += u64::from(ran);
                listed = Some(next);
                if next == 0 {
                    finished = true;
                    break;
                }
            }
            if !finished {
                return Err(DispatchError::TooManyRounds {
                    rounds: kernels.max_rounds,
                });
            }
            // The finish kernel, unless a listed tile's round did its work (`TileList`).
            if kernels.tile_list.is_some_and(|t| t.accumulates) {
                wait(gpu)?;
            } else {
                let finish = kernels.finish;
                let begin = Instant::now();
                submit(gpu, finish.label(), "wavefront finish", |e| {
                    dispatch_kernel(
                        &mut begin_pass(e, finish.label()),
                        finish,
                        RoundDispatch::Tile,
                        &groups[finish_group],
                    );
                })?;
                wait(gpu)?;
                if timed {
                    add_stage_ms(&mut report.stage_ms, finish.label(), elapsed_ms(begin));
                }
            }
            report.dispatch.batches += 1;
            progress(done as u32 + 1, total);
        }
        report.dispatch.dispatch_ms = elapsed_ms(start);
        Ok(report)
    }
}

/// A round's dispatches as runs: a direct dispatch alone, or consecutive indirect ones from the
/// same counts (copied once, before the first).
enum Run {
    /// The round's kernel at this index, dispatched over the tile or as a row.
    Direct(usize),
    /// The round's kernels at these indices, indirectly from the counts at `counts`.
    Indirect { counts: u64, kernels: Vec<usize> },
}

/// The kernels of `round` cut into [`Run`]s.
fn round_runs(round: &[(&Kernel, RoundDispatch)]) -> Vec<Run> {
    let mut runs: Vec<Run> = Vec::new();
    for (at, (_, how)) in round.iter().enumerate() {
        match (how, runs.last_mut()) {
            (RoundDispatch::Indirect(c), Some(Run::Indirect { counts, kernels }))
                if c == counts =>
            {
                kernels.push(at)
            }
            (RoundDispatch::Indirect(c), _) => runs.push(Run::Indirect {
                counts: *c,
                kernels: vec![at],
            }),
            (RoundDispatch::Tile | RoundDispatch::Row(_), _) => runs.push(Run::Direct(at)),
        }
    }
    runs
}

/// Records into a new command buffer labelled `label` with `encode` and submits it, in an error
/// scope (`what` names it in an error).
fn submit(
    gpu: &Gpu,
    label: &str,
    what: &'static str,
    encode: impl FnOnce(&mut wgpu::CommandEncoder),
) -> Result<(), DispatchError> {
    let ((), error) = gpu.scoped(|| {
        let mut encoder = gpu
            .device()
            .create_command_encoder(&wgpu::CommandEncoderDescriptor { label: Some(label) });
        encode(&mut encoder);
        gpu.queue().submit([encoder.finish()]);
    });
    wgpu_result(what, error)
}

/// A compute pass labelled `label` on `encoder`.
fn begin_pass<'e>(encoder: &'e mut wgpu::CommandEncoder, label: &str) -> wgpu::ComputePass<'e> {
    encoder.begin_compute_pass(&wgpu::ComputePassDescriptor {
        label: Some(label),
        timestamp_writes: None,
    })
}
