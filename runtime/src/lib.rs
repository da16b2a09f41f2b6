//! `rtc-runtime`: the thin wgpu runtime of rtc (scenes, BVHs, GPU buffers, dispatch, images).
