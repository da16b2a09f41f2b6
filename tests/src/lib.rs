//! Shared helpers of the integration suites (golden-file comparison, test discovery).
