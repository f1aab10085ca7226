//! The command line, declared once with clap: parsing, `--help` of every command,
//! `--version`, suggestions for mistyped commands and flags, and shell completions
//! all come from these definitions.

use clap::{Args, Parser, Subcommand, ValueEnum};
use std::path::PathBuf;

/// garmentcode: parametric sewing patterns (a Rust implementation of GarmentCode).
#[derive(Parser, Debug)]
#[command(name = "garmentcode", version, propagate_version = true, arg_required_else_help = true)]
#[command(after_help = "Run `garmentcode <COMMAND> --help` for the options of a command.")]
pub struct Cli {
    /// What to do.
    #[command(subcommand)]
    pub command: Command,
}

/// The sub-commands.
#[derive(Subcommand, Debug)]
pub enum Command {
    /// Build a garment from a design and a body into a folder.
    #[command(long_about = BUILD_ABOUT)]
    Build(BuildArgs),
    /// Print the design space: every parameter with its type, range, default and sampling probability.
    Schema(SchemaArgs),
    /// Validate a pattern (specification.json): structural errors and warnings.
    #[command(long_about = CHECK_ABOUT)]
    Check(CheckArgs),
    /// Re-emit a pattern and draw it (pattern.svg, pattern.png).
    #[command(long_about = RENDER_ABOUT)]
    Render(RenderArgs),
    /// Judge whether two patterns are the same garment by geometry.
    #[command(long_about = COMPARE_ABOUT)]
    Compare(CompareArgs),
    /// Make a dataset of random garments, or replay one sample of it.
    #[command(long_about = SAMPLE_ABOUT)]
    Sample(SampleArgs),
    /// Mesh a pattern for cloth simulation: the reference's box mesh and its files.
    #[command(long_about = MESH_ABOUT)]
    Mesh(MeshArgs),
    /// Drape a garment on a body: the draped mesh (OBJ, GLB), its figures and front and back pictures.
    #[command(long_about = DRAPE_ABOUT)]
    Drape(DrapeArgs),
    /// Patterns to print, cut and sew: tiled and one-sheet PDF, SVG, DXF-AAMA and a cutting layout.
    #[command(long_about = PRINT_ABOUT)]
    Print(PrintArgs),
    /// Run the web configurator (a page with a control for every parameter, and its JSON API).
    #[command(long_about = SERVE_ABOUT)]
    Serve(ServeArgs),
    /// Write the measuring guide: how to take every body measurement, with a figure of where the tape goes.
    Guide(GuideArgs),
    /// Print a shell completion script (e.g. `garmentcode completions bash > ~/.local/share/bash-completion/completions/garmentcode`).
    Completions(CompletionsArgs),
}

const BUILD_ABOUT: &str = "\
Build a garment: DIR/specification.json, pattern.svg, pattern.png, design_params.yaml, \
body_measurements.yaml and checks.json.

The reference's checks (design filter, total length, self-intersection) are printed as warnings; \
--strict rejects a design that fails one (exit 1, nothing written).

The output folder is written whole: into a temporary folder first, then swapped in. An existing \
folder is replaced only when it holds nothing but files garmentcode writes (or with --force).";

const MESH_ABOUT: &str = "\
Mesh a pattern for cloth simulation, as the reference's BoxMesh does: every panel triangulated at \
--resolution cm, placed in 3D, the two sides of every stitch merged. DIR gets NAME_boxmesh.obj (cm, \
with per-corner UVs), NAME_material.mtl, NAME_sim_segmentation.txt (a panel name or stitch labels \
per vertex), NAME_orig_lens.pickle (2D rest lengths), NAME_vertex_labels.yaml, NAME_specification.json, \
and NAME_sim_mesh.obj (metres) and NAME_boxmesh.ply (segments as vertex attributes). NAME is the \
specification's file name without _specification.json (a plain specification.json: its folder's name).

The output folder is written whole, as `build` writes it.";

const DRAPE_ABOUT: &str = "\
Drape a garment on a body with the reference's cloth simulation (XPBD, its default fabric and \
stopping rules). The garment is a pattern (SPEC.json) or a design (a built-in name or a design \
file, built on --body). DIR gets the box mesh files (as `garmentcode mesh` writes them) and \
NAME_sim.obj (the draped mesh, cm, y up, the box mesh's vertices and faces in its order), \
NAME_sim.glb (glTF 2.0, metres, with the body), NAME_drape.json (frames, time, converged, body \
penetrations, self-intersections, seam and fabric strain, the settings, body and fabric) and \
NAME_render_front.png, NAME_render_back.png.

The body mesh is the one of --body (`BodyMesh::for_body`), or --body-mesh FILE.obj (a closed mesh in metres, y \
up). --fabric is a built-in fabric (default, mid_bending, minimal_bending: the reference's \
presets) or a fabric file (YAML, `fabric:` with spring_ke, spring_kd, garment_edge_ke, \
garment_edge_kd, fabric_density, fabric_thickness, fabric_friction, and `base: NAME`).

Progress goes to stderr. Exit status: 0 when the drape settled; 3 when it did not (the frame or \
time limit was reached) or it failed one of the reference's limits (more than 35 body \
penetrations or 300 self-intersections): the files are written all the same, and \
NAME_drape.json lists the reasons under `fails`; 2 for bad input, with nothing written.

The output folder is written whole, as `build` writes it.";

const PRINT_ABOUT: &str = "\
Turn a pattern into pieces a person can print, cut and sew: each panel with its seam allowance \
(the sew line dashed inside the cut line), notches where seams meet, a grainline, the cut count \
(mirrored pairs and pieces cut on the fold are found) and labels. DIR gets pattern-tiled.pdf (A4 or \
Letter pages at 1:1 with a cover page and page map), pattern-sheet.pdf and pattern-sheet.svg (every \
piece on one sheet, A0 or a roll width), pattern.dxf (DXF-AAMA, R12, millimetres) and \
cutting-layout.svg/.txt (the pieces on the fabric width and the length of fabric needed).

The output folder is written whole, as `build` writes it.";

const CHECK_ABOUT: &str = "\
Validate a pattern: errors (open loops, bad indices, degenerate edges, dangling stitches, edges \
stitched twice) and warnings (self-intersections; stitched edges of different lengths, which are \
gathers when the design asks for them). Exit 1 on errors. With --strict also on the warnings \
`build --strict` rejects (self-intersections); length differences are only reported.";

const RENDER_ABOUT: &str = "\
Re-emit DIR/specification.json and draw DIR/pattern.svg and DIR/pattern.png. A pattern with \
structural errors (see `garmentcode check`) is refused unless --force, which draws it anyway.";

const COMPARE_ABOUT: &str = "\
Judge whether two patterns are the same garment by geometry: outlines, placement, perimeters and \
stitches within --tol (vertex order and JSON layout do not matter). With --cases, every case folder \
(specification.json or error.txt) of EXPECTED_DIR against the same folder in ACTUAL_DIR. Exit 0 when \
all pass, else 1.

Sleeve, cuff and hood panels come from a numerical fit that is chaotic in the reference (tiny \
changes of input give visibly different curves), so by default they are judged by how they sew \
(lengths of the seams they share, and placement) rather than point by point; reports call them \
\"chaotic panels\". --no-chaotic-rule compares them point by point too.";

const SAMPLE_ABOUT: &str = "\
A dataset of N random garments: DIR/rand_0000000 ... each with rand_NNNNNNN_specification.json (and \
_pattern.svg/.png as asked), design_params.yaml, body_measurements.yaml and sample_info.json, and \
DIR/dataset_properties.yaml (types, rejections by reason, time).

Sample i depends on (S, i) alone: the same with any --jobs and in any shard. Designs failing the \
reference's filters are drawn again (up to 100 times). A rerun into DIR skips finished samples.

With --layout shards[:N], the samples go into tar shards of N samples (default 1000): \
DIR/shard-000000.tar holds samples 0 to N-1, each file named after its sample \
(rand_0000042.specification.json, ...), with DIR/index.jsonl listing every sample's shard and \
garment type. A shard is the same whatever --jobs and --shard; with --shard I/K a task writes \
the shards whose number k has k % K == I. --unpack SHARD.tar... --out DIR gives the folders back.

With --replay INDEX[:ATTEMPT], rebuild one sample, or one attempt of it (also a rejected one), into \
DIR as `build` would (drawings included), and print the filters' verdict.";

const SERVE_ABOUT: &str = "\
The web configurator: a page with a control for every design parameter, the body measurements and \
the pattern drawn live, plus its JSON API (GET /api/schema, POST /api/pattern, ...; see README). \
Listens on loopback unless --host says otherwise; --port 0 picks a free port. Prints the page's \
address. Ctrl-C stops it after the requests in progress.";

/// Drawing layout.
#[derive(ValueEnum, Clone, Copy, Debug, PartialEq, Eq)]
pub enum LayoutArg {
    /// Panels where the reference draws them, as on the body.
    Placed,
    /// Panels side by side without overlap, in rows at most 150 cm wide, to print and cut from.
    Flat,
}

impl From<LayoutArg> for garmentcode::draw::Layout {
    fn from(l: LayoutArg) -> Self {
        match l {
            LayoutArg::Placed => garmentcode::draw::Layout::Placed,
            LayoutArg::Flat => garmentcode::draw::Layout::Flat,
        }
    }
}

/// PNG options of the drawings (`build`, `render`).
#[derive(Args, Debug, Clone)]
pub struct PngArgs {
    /// PNG resolution in dots per inch (default: the reference's 3 px per cm, about 7.6 dpi).
    #[arg(long, value_name = "DPI", value_parser = positive_dpi)]
    pub dpi: Option<f64>,
    /// PNG background (default: white, for reading; `none` keeps it transparent, as the reference's PNG).
    #[arg(long, value_enum, default_value_t = BackgroundArg::White)]
    pub background: BackgroundArg,
}

/// PNG background.
#[derive(ValueEnum, Clone, Copy, Debug, PartialEq, Eq)]
pub enum BackgroundArg {
    /// Transparent outside the panels.
    None,
    /// White.
    White,
}

impl PngArgs {
    /// The drawing options for `layout` with these PNG settings.
    pub fn draw_options(&self, layout: garmentcode::draw::Layout) -> garmentcode::draw::DrawOptions {
        let mut o = garmentcode::draw::DrawOptions { layout, ..Default::default() };
        if let Some(dpi) = self.dpi {
            o.px_per_cm = dpi / 2.54;
        }
        if self.background == BackgroundArg::White {
            o.background = Some([255, 255, 255]);
        }
        o
    }
}

fn positive_dpi(s: &str) -> Result<f64, String> {
    match s.trim().parse::<f64>() {
        Ok(x) if x.is_finite() && x > 0.0 && x <= 1200.0 => Ok(x),
        _ => Err(format!("expects a resolution in dots per inch, above 0 and at most 1200, got '{s}'")),
    }
}

/// A built-in name or a file: any text is accepted (`load_design` and `load_body`
/// judge it), and the built-in names are offered by shell completion.
#[derive(Clone)]
pub struct NameOrFile(fn() -> Vec<&'static str>);

impl clap::builder::TypedValueParser for NameOrFile {
    type Value = String;

    fn parse_ref(&self, cmd: &clap::Command, arg: Option<&clap::Arg>, value: &std::ffi::OsStr) -> Result<String, clap::Error> {
        clap::builder::StringValueParser::new().parse_ref(cmd, arg, value)
    }

    fn possible_values(&self) -> Option<Box<dyn Iterator<Item = clap::builder::PossibleValue> + '_>> {
        Some(Box::new(self.0().into_iter().map(clap::builder::PossibleValue::new)))
    }
}

/// `--design`: a built-in design or a design file.
fn design_arg() -> NameOrFile {
    NameOrFile(|| garments::builtin::DESIGNS.iter().map(|(n, _)| *n).collect())
}

/// `--body`: a built-in body or a body file.
fn body_arg() -> NameOrFile {
    NameOrFile(|| garments::builtin::BODIES.iter().map(|(n, _)| *n).collect())
}

/// `garmentcode build`.
#[derive(Args, Debug)]
pub struct BuildArgs {
    /// Design: a design file (.yaml) or a built-in design, a preset (t-shirt, fitted-dress, sundress, shirt-dress, jumpsuit).
    #[arg(short, long, value_name = "FILE.yaml|NAME", default_value = garments::builtin::DEFAULT_DESIGN, value_parser = design_arg(), hide_possible_values = true)]
    pub design: String,
    /// Body: a body file (.yaml) or a built-in body (mean_all, mean_female, mean_male, f_smpl_average_A40, m_smpl_average_A40).
    #[arg(short, long, value_name = "NAME|FILE.yaml", default_value = garments::builtin::DEFAULT_BODY, value_parser = body_arg(), hide_possible_values = true)]
    pub body: String,
    /// Output folder.
    #[arg(short, long, value_name = "DIR")]
    pub out: PathBuf,
    /// Pattern name written into the specification (default: the design's name).
    #[arg(short, long)]
    pub name: Option<String>,
    /// Reject a design that fails one of the reference's checks (exit 1, nothing written).
    #[arg(long)]
    pub strict: bool,
    /// What to write besides the pattern and its inputs: `svg` and `png` drawings and
    /// the simulation box `mesh` (NAME_boxmesh.obj and the files `garmentcode mesh`
    /// writes), `print`, `drape` (the mesh and the drape files of `garmentcode drape`; exit
    /// status 3 when the drape did not settle); `json` (the pattern, design, body and checks) is always written.
    #[arg(long, value_enum, value_delimiter = ',', value_name = "FORMATS", default_value = "json,svg,png")]
    pub formats: Vec<BuildFormat>,
    /// Do not draw pattern.png (the same as leaving `png` out of --formats).
    #[arg(long)]
    pub no_png: bool,
    /// Spacing of the mesh's boundary vertices in cm, with `--formats ...,mesh`.
    #[arg(long, value_name = "CM", default_value_t = 1.0, value_parser = positive_cm)]
    pub mesh_resolution: f64,
    /// With `--formats ...,drape`: the body mesh to drape on (OBJ, closed, metres, y up) instead of the mesh of --body.
    #[arg(long, value_name = "FILE.obj")]
    pub body_mesh: Option<PathBuf>,
    /// With `--formats ...,drape`: fabric, frame and time limits.
    #[command(flatten)]
    pub sim: SimArgs,
    /// Drawing layout.
    #[arg(short, long, value_enum, default_value_t = LayoutArg::Placed)]
    pub layout: LayoutArg,
    /// PNG resolution and background.
    #[command(flatten)]
    pub png: PngArgs,
    /// Replace an output folder that holds files garmentcode did not write.
    #[arg(short, long)]
    pub force: bool,
}

/// What `build` writes.
#[derive(ValueEnum, Clone, Copy, Debug, PartialEq, Eq)]
pub enum BuildFormat {
    /// specification.json, design_params.yaml, body_measurements.yaml, checks.json (always).
    Json,
    /// pattern.svg.
    Svg,
    /// pattern.png.
    Png,
    /// The simulation box mesh (as `garmentcode mesh` writes it).
    Mesh,
    /// The printable pattern (as `garmentcode print` writes it with its defaults).
    Print,
    /// The garment draped on the body, with the mesh (as `garmentcode drape` writes it).
    Drape,
}

/// `garmentcode drape`.
#[derive(Args, Debug)]
pub struct DrapeArgs {
    /// The garment: a pattern (a .json file) or a design (a design file .yaml or a built-in design).
    #[arg(value_name = "SPEC.json|DESIGN")]
    pub garment: String,
    /// Output folder.
    #[arg(short, long, value_name = "DIR")]
    pub out: PathBuf,
    /// Body: a body file (.yaml) or a built-in body; its measurements place the attachments (and build a design).
    #[arg(short, long, value_name = "NAME|FILE.yaml", default_value = garments::builtin::DEFAULT_BODY, value_parser = body_arg(), hide_possible_values = true)]
    pub body: String,
    /// The body mesh to drape on (OBJ, closed, metres, y up), instead of the mesh of --body.
    #[arg(long, value_name = "FILE.obj")]
    pub body_mesh: Option<PathBuf>,
    /// Fabric, frame and time limits.
    #[command(flatten)]
    pub sim: SimArgs,
    /// Spacing of the mesh's boundary vertices in cm.
    #[arg(short, long, value_name = "CM", default_value_t = 1.0, value_parser = positive_cm)]
    pub resolution: f64,
    /// File name prefix (default: from the specification's file name, or the design's name).
    #[arg(long)]
    pub name: Option<String>,
    /// No progress on stderr.
    #[arg(short, long)]
    pub quiet: bool,
    /// Replace an output folder that holds files garmentcode did not write.
    #[arg(short, long)]
    pub force: bool,
}

/// Options of a drape (`drape`, and `build`/`sample` with the `drape` format).
#[derive(Args, Debug, Clone)]
pub struct SimArgs {
    /// Fabric: a built-in fabric (default, mid_bending, minimal_bending) or a fabric file (.yaml).
    #[arg(long, value_name = "NAME|FILE.yaml", default_value = "default", value_parser = NameOrFile(|| garmentcode_drape::fabric::BUILTIN.to_vec()), hide_possible_values = true)]
    pub fabric: String,
    /// Most frames simulated (60 a second; the reference's 2400 by default).
    #[arg(long, value_name = "N", value_parser = clap::value_parser!(u32).range(1..=garmentcode_drape::solver::MAX_FRAMES as i64))]
    pub max_frames: Option<u32>,
    /// Most seconds a simulation may take (the reference's 600 by default); then it stops, unsettled.
    #[arg(long, value_name = "S", default_value_t = 600.0, value_parser = positive_seconds)]
    pub max_seconds: f64,
}

impl Default for SimArgs {
    fn default() -> SimArgs {
        SimArgs { fabric: "default".into(), max_frames: None, max_seconds: 600.0 }
    }
}

fn positive_seconds(s: &str) -> Result<f64, String> {
    match s.trim().parse::<f64>() {
        Ok(x) if x.is_finite() && x > 0.0 && x <= 1e6 => Ok(x),
        _ => Err(format!("expects a number of seconds above 0 and at most 1000000, got '{s}'")),
    }
}

/// Formats of `schema`.
#[derive(ValueEnum, Clone, Copy, Debug, PartialEq, Eq)]
pub enum SchemaFormat {
    /// The design space in the reference's layout (its `default.yaml`): every parameter's
    /// type, range, default `v` and sampling probability, as `sample --design-space` reads it.
    /// With --design, that design's values as `v` instead: a design file that builds.
    ReferenceYaml,
    /// A JSON Schema of design files.
    JsonSchema,
    /// One line per parameter.
    Table,
}

/// `garmentcode schema`.
#[derive(Args, Debug)]
pub struct SchemaArgs {
    /// Output format.
    #[arg(long, value_enum, default_value_t = SchemaFormat::ReferenceYaml)]
    pub format: SchemaFormat,
    /// A starting design to edit and build instead of the design space: a built-in
    /// design (a preset: t-shirt, fitted-dress, sundress, shirt-dress, jumpsuit) or a
    /// design file, written with every parameter's range and probability.
    #[arg(short, long, value_name = "NAME|FILE.yaml", value_parser = design_arg(), hide_possible_values = true)]
    pub design: Option<String>,
    /// With the parameters past the reference (`design.extension`: pockets, pleats, diamond darts, one-piece sleeves, folded cuffs and collars) after the reference's, as `sample --extended` draws them.
    #[arg(long)]
    pub extended: bool,
}

/// Formats of `check`.
#[derive(ValueEnum, Clone, Copy, Debug, PartialEq, Eq)]
pub enum CheckFormat {
    /// One line per problem and a summary.
    Text,
    /// A JSON report.
    Json,
}

/// `garmentcode check`.
#[derive(Args, Debug)]
pub struct CheckArgs {
    /// The pattern (specification.json).
    #[arg(value_name = "SPEC.json")]
    pub file: String,
    /// Also exit 1 on the warnings `build --strict` rejects (self-intersections).
    #[arg(long)]
    pub strict: bool,
    /// Output format.
    #[arg(long, value_enum, default_value_t = CheckFormat::Text)]
    pub format: CheckFormat,
}

/// `garmentcode render`.
#[derive(Args, Debug)]
pub struct RenderArgs {
    /// The pattern (specification.json).
    #[arg(value_name = "SPEC.json")]
    pub file: String,
    /// Output folder.
    #[arg(short, long, value_name = "DIR")]
    pub out: PathBuf,
    /// Do not draw pattern.png.
    #[arg(long)]
    pub no_png: bool,
    /// Drawing layout.
    #[arg(short, long, value_enum, default_value_t = LayoutArg::Placed)]
    pub layout: LayoutArg,
    /// PNG resolution and background.
    #[command(flatten)]
    pub png: PngArgs,
    /// Draw a pattern with structural errors anyway, and replace an output folder
    /// that holds files garmentcode did not write.
    #[arg(short, long)]
    pub force: bool,
}

/// `garmentcode compare`.
#[derive(Args, Debug)]
pub struct CompareArgs {
    /// The expected pattern (or case folder with --cases).
    #[arg(value_name = "EXPECTED")]
    pub expected: PathBuf,
    /// The pattern to judge (or case folder with --cases).
    #[arg(value_name = "ACTUAL")]
    pub actual: PathBuf,
    /// Compare every case folder of EXPECTED with the same folder in ACTUAL.
    #[arg(long)]
    pub cases: bool,
    /// Tolerance in cm.
    #[arg(short, long, value_name = "CM", default_value_t = 0.05, value_parser = positive_cm)]
    pub tol: f64,
    /// Fail on any difference the tolerance does not cover (also vertex counts).
    #[arg(long)]
    pub strict: bool,
    /// Compare sleeve, cuff and hood panels point by point too.
    #[arg(long)]
    pub no_chaotic_rule: bool,
    /// Every difference and note, not only the first three.
    #[arg(short, long)]
    pub verbose: bool,
}

fn positive_cm(s: &str) -> Result<f64, String> {
    match s.trim().parse::<f64>() {
        Ok(x) if x.is_finite() && x > 0.0 => Ok(x),
        _ => Err(format!("expects a positive number of cm, got '{s}'")),
    }
}

fn non_negative_cm(s: &str) -> Result<f64, String> {
    match s.trim().parse::<f64>() {
        Ok(x) if x.is_finite() && x >= 0.0 => Ok(x),
        _ => Err(format!("expects a non-negative number of cm, got '{s}'")),
    }
}

/// `garmentcode sample`.
#[derive(Args, Debug)]
pub struct SampleArgs {
    /// Number of samples (not with --replay).
    #[arg(short, long = "n", value_name = "N", required_unless_present_any = ["replay", "unpack"], value_parser = clap::value_parser!(u64).range(1..))]
    pub n: Option<u64>,
    /// Seed: any whole number from 0 to 2^64-1.
    #[arg(short, long, value_name = "S", required_unless_present = "unpack")]
    pub seed: Option<u64>,
    /// Output folder (/dev/null: make every sample, its files too, and discard them; nothing is written).
    #[arg(short, long, value_name = "DIR")]
    pub out: PathBuf,
    /// A design file whose ranges and probabilities replace the built-in ones.
    #[arg(long, value_name = "FILE.yaml")]
    pub design_space: Option<String>,
    /// Also draw the parameters past the reference (`design.extension`: pockets, pleats, diamond darts, folded cuffs and collars); the reference's parameters are drawn as without it.
    #[arg(long)]
    pub extended: bool,
    /// Built-in body names or body files separated by commas, or a folder of body files (default mean_all).
    #[arg(long, value_name = "NAME,NAME|DIR")]
    pub bodies: Option<String>,
    /// Threads (default: all cores).
    #[arg(short, long, value_name = "J", value_parser = clap::value_parser!(u64).range(1..))]
    pub jobs: Option<u64>,
    /// Only the samples i with i % K == I (0 <= I < K).
    #[arg(long, value_name = "I/K")]
    pub shard: Option<String>,
    /// Files per sample: a list of json, svg, png, mesh (the simulation box mesh at 1 cm), drape (the mesh and the garment draped on its body, as `garmentcode drape` writes it; a failed drape is recorded in the summary) (default json; with --replay json,svg,png).
    #[arg(long, value_name = "LIST")]
    pub formats: Option<String>,
    /// Rebuild one sample, or one attempt of it, into DIR as `build` would.
    #[arg(short, long, value_name = "INDEX[:ATTEMPT]")]
    pub replay: Option<String>,
    /// Dataset layout: a folder per sample (default), or tar shards of N samples (default 1000).
    #[arg(long, value_name = "folders|shards[:N]", conflicts_with = "replay")]
    pub layout: Option<String>,
    /// Unpack shards into DIR as the folder layout (a folder per sample, and the dataset's summary when the shards come from one folder).
    #[arg(long, value_name = "SHARD.tar", num_args = 1.., conflicts_with_all = ["n", "replay", "layout", "shard", "design_space", "bodies", "formats", "jobs"])]
    pub unpack: Vec<PathBuf>,
    /// With `--formats ...,drape`: fabric, frame and time limits of every drape.
    #[command(flatten)]
    pub sim: SimArgs,
}

/// `garmentcode serve`.
#[derive(Args, Debug)]
pub struct ServeArgs {
    /// Port (0 picks a free one).
    #[arg(short, long, default_value_t = 8000)]
    pub port: u16,
    /// Address to listen on: loopback by default; 0.0.0.0 makes the configurator reachable from other machines.
    #[arg(long, default_value = "127.0.0.1")]
    pub host: String,
}

/// `garmentcode mesh`.
#[derive(Args, Debug)]
pub struct MeshArgs {
    /// The pattern (specification.json).
    #[arg(value_name = "SPEC.json")]
    pub file: String,
    /// Output folder.
    #[arg(short, long, value_name = "DIR")]
    pub out: PathBuf,
    /// Spacing of the boundary vertices in cm (interior edges up to 1.43 times it).
    #[arg(short, long, value_name = "CM", default_value_t = 1.0)]
    pub resolution: f64,
    /// File name prefix (default: from the specification's file name).
    #[arg(long)]
    pub name: Option<String>,
    /// Replace an output folder that holds files garmentcode did not write.
    #[arg(short, long)]
    pub force: bool,
}

/// `garmentcode print`.
#[derive(Args, Debug)]
pub struct PrintArgs {
    /// The pattern (specification.json); with --sizes or --size-chart, the design (a design file or a built-in design) built on each size.
    #[arg(value_name = "SPEC.json|DESIGN")]
    pub file: String,
    /// A size run: the design built on each of these bodies (built-in names or body files), printed nested.
    #[arg(long, value_name = "BODY,BODY,...", value_delimiter = ',', num_args = 1.., conflicts_with = "size_chart")]
    pub sizes: Vec<String>,
    /// A size run from a size chart file (sizes by a few measurements over a built-in body; see the README).
    #[arg(long, value_name = "FILE.yaml")]
    pub size_chart: Option<String>,
    /// Output folder.
    #[arg(short, long, value_name = "DIR")]
    pub out: PathBuf,
    /// Paper: `a4` or `letter` for the tiled pages, `a0` or `roll:WIDTH_CM` for the one-sheet
    /// (the other one keeps its default: A4 pages, an A0-wide sheet).
    #[arg(long, value_name = "a4|letter|a0|roll:WIDTH_CM", default_value = "a4", value_parser = garmentcode::fabricate::Paper::parse)]
    pub paper: garmentcode::fabricate::Paper,
    /// Seam allowance of every edge, in cm.
    #[arg(long, value_name = "CM", default_value_t = 1.0, value_parser = non_negative_cm)]
    pub seam: f64,
    /// Allowance of hems (edges labelled lower_interface that are not stitched), in cm.
    #[arg(long, value_name = "CM", value_parser = non_negative_cm)]
    pub hem: Option<f64>,
    /// Allowance of one panel (PANEL=CM) or one of its edges (PANEL:EDGE=CM); repeatable.
    #[arg(long = "seam-edge", value_name = "PANEL[:EDGE]=CM", value_parser = garmentcode::fabricate::EdgeSeam::parse)]
    pub seam_edges: Vec<garmentcode::fabricate::EdgeSeam>,
    /// Fabric width for the cutting layout, in cm.
    #[arg(long, value_name = "CM", default_value_t = 140.0, value_parser = positive_cm)]
    pub fabric_width: f64,
    /// Garment name on the labels (default: from the specification's file or folder name).
    #[arg(long)]
    pub garment: Option<String>,
    /// Size on the labels, e.g. the body's name (a size run names each size by its body or chart entry).
    #[arg(long, default_value = "unspecified")]
    pub size: String,
    /// Replace an output folder that holds files garmentcode did not write.
    #[arg(short, long)]
    pub force: bool,
}

/// `garmentcode guide`.
#[derive(Args, Debug)]
pub struct GuideArgs {
    /// Output folder: measuring-guide.html (printable) and one figure per measurement (figure-NAME.svg).
    #[arg(short, long, value_name = "DIR")]
    pub out: PathBuf,
    /// Body the figures are drawn on: a body file (.yaml) or a built-in body.
    #[arg(short, long, value_name = "NAME|FILE.yaml", default_value = garments::builtin::DEFAULT_BODY, value_parser = body_arg(), hide_possible_values = true)]
    pub body: String,
    /// Replace an output folder that holds files garmentcode did not write.
    #[arg(short, long)]
    pub force: bool,
}

/// `garmentcode completions`.
#[derive(Args, Debug)]
pub struct CompletionsArgs {
    /// The shell.
    #[arg(value_enum)]
    pub shell: clap_complete::Shell,
}

#[cfg(test)]
mod tests {
    use super::*;
    use clap::CommandFactory;

    #[test]
    fn definitions_are_consistent() {
        Cli::command().debug_assert();
    }
}
