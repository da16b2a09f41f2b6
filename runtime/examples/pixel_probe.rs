//! Prints the linear RGBA values of chosen pixels of an image (EXR, HDR, PNG, JPEG): a debugging aid
//! for kernels, e.g. `cargo run -p rtc-runtime --example pixel_probe -- out.exr 80,60 10,10`.

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let Some(path) = args.get(1) else {
        eprintln!("usage: pixel_probe IMAGE X,Y …");
        std::process::exit(2);
    };
    let img = match rtc_runtime::image_out::read_image(std::path::Path::new(path)) {
        Ok(img) => img,
        Err(e) => {
            eprintln!("error: {e}");
            std::process::exit(1);
        }
    };
    for xy in &args[2..] {
        let parsed = xy
            .split_once(',')
            .and_then(|(x, y)| Some((x.parse::<u32>().ok()?, y.parse::<u32>().ok()?)));
        match parsed.and_then(|(x, y)| img.get(x, y)) {
            Some(px) => println!("{xy}: {px:?}"),
            None => println!("{xy}: outside the image"),
        }
    }
}
