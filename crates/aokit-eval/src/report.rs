//! Comparison reports: a CSV for tools, a Markdown table for terminals and docs, and one
//! self-contained HTML page with images, error maps, tables and an error-versus-cost chart.

mod chart;
mod csv;
mod html;
mod markdown;
mod text;

use crate::metrics::{Metrics, SequenceMetrics};

/// One method at one preset, scored against a view's reference.
///
/// ```
/// use aokit_eval::{compare, report::MethodResult};
/// // A 2x1 image: one pixel right, one 0.2 too bright.
/// let (ao, reference, mask) = ([0.5, 0.9], [0.5, 0.7], [true, true]);
/// let all = compare([2, 1], &ao, &reference, &mask);
/// let result = MethodResult {
///     method: "gtao".into(),
///     preset: "high".into(),
///     all,
///     edges: compare([2, 1], &ao, &reference, &[false, true]),
///     grazing: compare([2, 1], &ao, &reference, &[false, false]),
///     sequence: None,
///     gpu_ms: None,
///     samples_per_pixel: 18,
///     ao_png: aokit_eval::encode_png_grey([2, 1], &ao)?,
///     error_png: Vec::new(),
/// };
/// assert!((result.all.bias - 0.1).abs() < 1e-6);
/// # Ok::<(), aokit_eval::EvalError>(())
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct MethodResult {
    /// Method name, such as `gtao`.
    pub method: String,
    /// Preset name, such as `high`.
    pub preset: String,
    /// Scores over every surface pixel.
    pub all: Metrics,
    /// Scores over pixels near depth edges only.
    pub edges: Metrics,
    /// Scores over surfaces seen nearly edge-on only (see
    /// [`grazing_mask`](crate::grazing_mask)), where methods that march in screen space lose
    /// most of the hemisphere.
    pub grazing: Metrics,
    /// Scores over a sequence of frames, when the run rendered one; `all`, `edges`, `grazing`
    /// and the images are then of its last frame.
    pub sequence: Option<SequenceMetrics>,
    /// Median GPU time of the AO passes per frame, when timestamps were available.
    pub gpu_ms: Option<f64>,
    /// AO samples per pixel, a cost measure that needs no GPU timer.
    pub samples_per_pixel: u32,
    /// The method's AO as a PNG.
    pub ao_png: Vec<u8>,
    /// Its signed error map (see [`error_map_rgb`](crate::error_map_rgb)) as a PNG.
    pub error_png: Vec<u8>,
}

/// One camera view: its reference and every method scored on it.
///
/// ```
/// use aokit_eval::report::ViewResult;
/// let view = ViewResult {
///     name: "room / front".into(),
///     reference_png: aokit_eval::encode_png_grey([1, 1], &[0.8])?,
///     methods: Vec::new(),
/// };
/// assert!(view.methods.is_empty());
/// # Ok::<(), aokit_eval::EvalError>(())
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct ViewResult {
    /// Shown as the section heading and in the `view` column.
    pub name: String,
    /// The reference AO as a PNG.
    pub reference_png: Vec<u8>,
    /// Results in the order they should be listed.
    pub methods: Vec<MethodResult>,
}

/// A whole comparison run.
///
/// ```
/// use aokit_eval::report::{Report, ViewResult};
/// let report = Report {
///     title: "aokit: AO methods against the ray-traced reference".into(),
///     notes: vec!["480x270 pixels".into()],
///     error_range: 0.5,
///     legend_png: Vec::new(),
///     views: vec![ViewResult {
///         name: "room / front".into(),
///         reference_png: Vec::new(),
///         methods: Vec::new(),
///     }],
/// };
/// assert!(report.markdown().contains("room / front"));
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct Report {
    /// Page title and Markdown heading.
    pub title: String,
    /// Free-text lines shown under the title (adapter, sizes, command line); empty ones are
    /// skipped.
    pub notes: Vec<String>,
    /// The error maps' saturation point, printed on the legend.
    pub error_range: f32,
    /// The colour bar from [`legend_rgb`](crate::legend_rgb) as a PNG.
    pub legend_png: Vec<u8>,
    /// The views, in order.
    pub views: Vec<ViewResult>,
}

impl Report {
    /// One row per view, method and preset under a header row; `gpu_ms` empty when unknown,
    /// full precision numbers (`inf` for an exact match's PSNR, `NaN` for an empty selection).
    ///
    /// ```
    /// # let report = aokit_eval::report::Report { title: "run".into(), notes: Vec::new(),
    /// #     error_range: 0.5, legend_png: Vec::new(), views: Vec::new() };
    /// let csv = report.csv();
    /// // A header row, then one row per view and method: none in an empty report.
    /// assert!(csv.starts_with("view,method,preset,samples_per_pixel,gpu_ms,"));
    /// assert_eq!(csv.lines().count(), 1);
    /// std::fs::write(std::env::temp_dir().join("metrics.csv"), csv)?;
    /// # Ok::<(), std::io::Error>(())
    /// ```
    pub fn csv(&self) -> String {
        csv::render(self)
    }

    /// The title, notes and a GitHub table per view.
    ///
    /// ```
    /// # let report = aokit_eval::report::Report { title: "run".into(), notes: Vec::new(),
    /// #     error_range: 0.5, legend_png: Vec::new(), views: Vec::new() };
    /// assert!(report.markdown().starts_with("# run"));
    /// ```
    pub fn markdown(&self) -> String {
        markdown::render(self)
    }

    /// Per method, a GitHub table of its RMSE (and bias) against the reference in every view,
    /// one row per preset: how a method's error moves with its cost.
    ///
    /// ```
    /// # let report = aokit_eval::report::Report { title: "run".into(), notes: Vec::new(),
    /// #     error_range: 0.5, legend_png: Vec::new(), views: Vec::new() };
    /// // One table per method that ran: none without views.
    /// assert_eq!(report.markdown_by_method(), "");
    /// ```
    pub fn markdown_by_method(&self) -> String {
        markdown::render_by_method(self)
    }

    /// One offline HTML page: images embedded as `data:` URIs, inline CSS and SVG, no scripts.
    ///
    /// ```
    /// # let report = aokit_eval::report::Report { title: "run".into(), notes: Vec::new(),
    /// #     error_range: 0.5, legend_png: Vec::new(), views: Vec::new() };
    /// let page = report.html();
    /// assert!(page.contains("<html") && !page.contains("<script"));
    /// ```
    pub fn html(&self) -> String {
        html::render(self)
    }
}
