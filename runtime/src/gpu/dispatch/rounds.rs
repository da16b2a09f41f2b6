//! Rounds of stage kernels over each tile: the wavefront model's dispatch.
//!
//! For each tile, a round is one command buffer: the *running* word is zeroed, the round's
//! kernels are dispatched in order (same tile parameters, each with its own bind group): over
//! the tile, as a row of workgroups, or indirectly from workgroup counts an earlier kernel of the round
//! stored in the flag's buffer, copied before the first of them ([`RoundDispatch`]); then the word
//! is copied to a mapped buffer and read. A round that found no path
//! running ends the tile's rounds; the finish kernel then runs once over the tile. Tiles run one
//! after the other, so one tile's path state is all the state buffer has to hold.
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
    /// The binding of the buffer holding the *running* word: zeroed before each round, set by the
    /// round's kernels to the number of paths the round ran, non-zero while some path still runs
    /// (and holding the indirect dispatches' workgroup counts).
    pub flag_binding: u32,
    /// The byte offset of that word (a multiple of 4).
    pub flag_offset: u64,
    /// Rounds a tile may take before the dispatch gives up.
    pub max_rounds: u32,
    /// Submit, wait for and time each dispatch alone ([`RoundsReport::stage_ms`]).
    pub timed: bool,
}

/// What a wavefront dispatch did.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct RoundsReport {
    /// Tiles, batches (one per tile) and times, as for a plain dispatch.
    pub dispatch: DispatchReport,
    /// Rounds run over all tiles (each tile's last round found nothing to do).
    pub rounds: u64,
    /// The *running* words read after each round, summed: the paths the rounds ran (for the
    /// wavefront model, the slots its listed stages ran over).
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
                size: 4,
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

        report.dispatch.flush_ms = flush_uploads(gpu)?;

        let start = Instant::now();
        let finish_group = groups.len() - 1;
        for (done, tile) in tiles.iter().enumerate() {
            // Fits: the buffer size was checked against u32 offsets in params_buffer.
            let offset = (u64::from(tile.tile_index) * stride) as u32;
            let mut finished = false;
            let dispatch =
                |pass: &mut wgpu::ComputePass<'_>, k: &Kernel, how: RoundDispatch, group| {
                    pass.set_pipeline(k.pipeline());
                    pass.set_bind_group(0, group, &[offset]);
                    match how {
                        RoundDispatch::Tile => {
                            let [x, y] = tile_workgroups(k, tile);
                            pass.dispatch_workgroups(x, y, 1);
                        }
                        RoundDispatch::Row(n) => pass.dispatch_workgroups(n, 1, 1),
                        RoundDispatch::Indirect(_) => {
                            pass.dispatch_workgroups_indirect(&indirect, 0);
                        }
                    }
                };
            // Copies the workgroup counts of an indirect dispatch unless the last copy holds them
            // (`copied`: its offset, forgotten after a direct dispatch, which may rewrite them).
            let copy_counts =
                |e: &mut wgpu::CommandEncoder, how: RoundDispatch, copied: &mut Option<u64>| {
                    match how {
                        RoundDispatch::Indirect(at) if *copied != Some(at) => {
                            e.copy_buffer_to_buffer(flag, at, &indirect, 0, Some(12));
                            *copied = Some(at);
                        }
                        RoundDispatch::Indirect(_) => {}
                        RoundDispatch::Tile | RoundDispatch::Row(_) => *copied = None,
                    }
                };
            let round = "rtc wavefront round";
            for _ in 0..kernels.max_rounds {
                if timed {
                    // The profile: zero the word, then each dispatch alone, waited for.
                    submit(gpu, round, "wavefront round", |e| {
                        e.clear_buffer(flag, flag_offset, Some(4))
                    })?;
                    let mut copied = None;
                    for (&(k, how), group) in kernels.round.iter().zip(&groups) {
                        let begin = Instant::now();
                        submit(gpu, k.label(), "wavefront round", |e| {
                            copy_counts(e, how, &mut copied);
                            dispatch(&mut begin_pass(e, k.label()), k, how, group)
                        })?;
                        wait(gpu)?;
                        add_stage_ms(&mut report.stage_ms, k.label(), elapsed_ms(begin));
                    }
                    submit(gpu, round, "wavefront round", |e| {
                        e.copy_buffer_to_buffer(flag, flag_offset, &staging, 0, Some(4));
                    })?;
                } else {
                    submit(gpu, round, "wavefront round", |e| {
                        e.clear_buffer(flag, flag_offset, Some(4));
                        // One pass for each run of dispatches between copies of counts.
                        let mut copied = None;
                        let mut next = kernels.round.iter().zip(&groups).peekable();
                        while let Some((&(k, how), group)) = next.next() {
                            copy_counts(e, how, &mut copied);
                            let mut pass = begin_pass(e, round);
                            dispatch(&mut pass, k, how, group);
                            while let Some((&(k, how), group)) = next.next_if(|(&(_, how), _)| {
                                !matches!(how, RoundDispatch::Indirect(at) if copied != Some(at))
                            }) {
                                if !matches!(how, RoundDispatch::Indirect(_)) {
                                    copied = None;
                                }
                                dispatch(&mut pass, k, how, group);
                            }
                        }
                        e.copy_buffer_to_buffer(flag, flag_offset, &staging, 0, Some(4));
                    })?;
                }
                report.rounds += 1;
                report.tile_slots += u64::from(tile.extent[0]) * u64::from(tile.extent[1]);
                let running = map_read(gpu, &staging, 4, |bytes| {
                    u32::from_le_bytes([bytes[0], bytes[1], bytes[2], bytes[3]])
                })?;
                report.running += u64::from(running);
                if running == 0 {
                    finished = true;
                    break;
                }
            }
            if !finished {
                return Err(DispatchError::TooManyRounds {
                    rounds: kernels.max_rounds,
                });
            }
            let finish = kernels.finish;
            let begin = Instant::now();
            submit(gpu, finish.label(), "wavefront finish", |e| {
                dispatch(
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
            report.dispatch.batches += 1;
            progress(done as u32 + 1, total);
        }
        report.dispatch.dispatch_ms = elapsed_ms(start);
        Ok(report)
    }
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
