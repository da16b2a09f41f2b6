//! Rounds of stage kernels over each tile: the wavefront model's dispatch.
//!
//! For each tile, a round is one command buffer: the *running* word is zeroed, the round's
//! kernels are dispatched in order over the tile (same tile parameters, each with its own bind
//! group), and the word is copied to a mapped buffer and read. A round that found no path
//! running ends the tile's rounds; the finish kernel then runs once over the tile. Tiles run one
//! after the other, so one tile's path state is all the state buffer has to hold.
//!
//! Invariants: a tile never runs more than the caller's `max_rounds` rounds (more is an error,
//! [`DispatchError::TooManyRounds`], not a hang); every wgpu call runs in an error scope.

use super::*;

/// The kernels of a wavefront dispatch.
pub struct RoundKernels<'a> {
    /// The kernels of one round, dispatched in this order (a kernel may appear twice).
    pub round: Vec<&'a Kernel>,
    /// The kernel run once over a tile after its last round.
    pub finish: &'a Kernel,
    /// The binding of the buffer holding the *running* word: zeroed before each round, set to a
    /// non-zero value by the round's kernels while some path still runs.
    pub flag_binding: u32,
    /// The byte offset of that word (a multiple of 4).
    pub flag_offset: u64,
    /// Rounds a tile may take before the dispatch gives up.
    pub max_rounds: u32,
}

/// What a wavefront dispatch did.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct RoundsReport {
    /// Tiles, batches (one per tile) and times, as for a plain dispatch.
    pub dispatch: DispatchReport,
    /// Rounds run over all tiles (each tile's last round found nothing to do).
    pub rounds: u64,
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
        let mut all: Vec<&Kernel> = kernels.round.clone();
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
        };
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

        report.dispatch.flush_ms = flush_uploads(gpu)?;

        let start = Instant::now();
        let finish_group = groups.len() - 1;
        for (done, tile) in tiles.iter().enumerate() {
            // Fits: the buffer size was checked against u32 offsets in params_buffer.
            let offset = (u64::from(tile.tile_index) * stride) as u32;
            let mut finished = false;
            for _ in 0..kernels.max_rounds {
                let ((), error) = gpu.scoped(|| {
                    let mut encoder =
                        gpu.device()
                            .create_command_encoder(&wgpu::CommandEncoderDescriptor {
                                label: Some("rtc wavefront round"),
                            });
                    encoder.clear_buffer(flag, flag_offset, Some(4));
                    {
                        let mut pass = encoder.begin_compute_pass(&wgpu::ComputePassDescriptor {
                            label: Some("rtc wavefront round"),
                            timestamp_writes: None,
                        });
                        for (k, group) in kernels.round.iter().zip(&groups) {
                            let [x, y] = tile_workgroups(k, tile);
                            pass.set_pipeline(k.pipeline());
                            pass.set_bind_group(0, group, &[offset]);
                            pass.dispatch_workgroups(x, y, 1);
                        }
                    }
                    encoder.copy_buffer_to_buffer(flag, flag_offset, &staging, 0, Some(4));
                    gpu.queue().submit([encoder.finish()]);
                });
                wgpu_result("wavefront round", error)?;
                report.rounds += 1;
                let running = map_read(gpu, &staging, 4, |bytes| bytes.iter().any(|&b| b != 0))?;
                if !running {
                    finished = true;
                    break;
                }
            }
            if !finished {
                return Err(DispatchError::TooManyRounds {
                    rounds: kernels.max_rounds,
                });
            }
            let ((), error) = gpu.scoped(|| {
                let mut encoder =
                    gpu.device()
                        .create_command_encoder(&wgpu::CommandEncoderDescriptor {
                            label: Some(kernels.finish.label()),
                        });
                {
                    let mut pass = encoder.begin_compute_pass(&wgpu::ComputePassDescriptor {
                        label: Some(kernels.finish.label()),
                        timestamp_writes: None,
                    });
                    let [x, y] = tile_workgroups(kernels.finish, tile);
                    pass.set_pipeline(kernels.finish.pipeline());
                    pass.set_bind_group(0, &groups[finish_group], &[offset]);
                    pass.dispatch_workgroups(x, y, 1);
                }
                gpu.queue().submit([encoder.finish()]);
            });
            wgpu_result("wavefront finish", error)?;
            wait(gpu)?;
            report.dispatch.batches += 1;
            progress(done as u32 + 1, total);
        }
        report.dispatch.dispatch_ms = elapsed_ms(start);
        Ok(report)
    }
}
