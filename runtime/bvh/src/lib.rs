//! `rtc-bvh`: BVH construction for rtc.
