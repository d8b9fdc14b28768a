//! The reducers of `schwenkbar-app` as yew state, and the one place their side effects are
//! carried out. `apply` returns the next state and its [`Effect`]s; the newtypes keep the last
//! list with a sequence number, and [`use_effects`] runs each list once after the render (so the
//! file input and the text area exist), reporting outcomes back as notices.

use std::ops::Deref;
use std::rc::Rc;

use schwenkbar_app::course::state::CourseState;
use schwenkbar_app::effect::{Effect, Reducer};
use schwenkbar_app::i18n::Text;
use schwenkbar_app::state::AppState;
use yew::prelude::*;

use crate::browser;

/// The effects of the last transition; `seq` changes with every non-empty list, so each list
/// runs once (and two lists are the same list when their `seq` is).
#[derive(Debug, Clone, Default)]
pub struct Pending {
    seq: u64,
    list: Rc<[Effect]>,
}

impl PartialEq for Pending {
    fn eq(&self, other: &Pending) -> bool {
        self.seq == other.seq
    }
}

impl Pending {
    fn next(&self, list: Vec<Effect>) -> Pending {
        match list.is_empty() {
            true => Pending { seq: self.seq, list: Rc::from([]) },
            false => Pending { seq: self.seq + 1, list: list.into() },
        }
    }
}

/// A page's state in yew (the trainer's [`AppState`] or the course's [`CourseState`]) with the
/// effects of its last transition.
#[derive(Debug, Clone, PartialEq)]
pub struct Shelled<S> {
    pub state: S,
    pub pending: Pending,
}

/// The trainer in yew.
pub type Trainer = Shelled<AppState>;
/// The course in yew.
pub type Course = Shelled<CourseState>;

impl<S> Shelled<S> {
    #[must_use]
    pub fn new((state, effects): (S, Vec<Effect>)) -> Shelled<S> {
        Shelled { state, pending: Pending::default().next(effects) }
    }
}

impl<S> Deref for Shelled<S> {
    type Target = S;
    fn deref(&self) -> &S {
        &self.state
    }
}

impl<S: Reducer> Reducible for Shelled<S> {
    type Action = S::Action;
    fn reduce(self: Rc<Self>, action: S::Action) -> Rc<Self> {
        if self.state.ignores(&action) {
            return self;
        }
        let (state, effects) = self.state.apply(action);
        Rc::new(Shelled { state, pending: self.pending.next(effects) })
    }
}

/// Where an effect's outcome goes and what the trainer's effects need of the page.
pub struct Shell {
    /// Reports an outcome (a failed save, "link copied") in the UI's dialog line or notice.
    pub notice: Callback<Text>,
    /// Satzfolge's timer fires `RunTick(step)`.
    pub tick: Callback<usize>,
    /// Cut the run's stock (`BuildStock`), after the screen is painted.
    pub build_stock: Callback<()>,
    /// The stock's first pass on by a share (`PassStock`), after the next paint.
    pub pass_stock: Callback<()>,
    /// Simulate the start's program (`Simulate`) once the simulator's code is there.
    pub simulate: Callback<()>,
    /// The app's root element (file input, text area).
    pub root: NodeRef,
    /// A lesson's trainer: the course wants the cursor's PLANE block.
    pub tell_course: Option<Callback<Option<String>>>,
}

impl Shell {
    /// A page other than the trainer (course, machine editor): it only saves and downloads, so
    /// it has no run timer, no stock and no course to tell.
    #[must_use]
    pub fn saving(notice: Callback<Text>, root: NodeRef) -> Shell {
        Shell {
            notice,
            tick: Callback::noop(),
            build_stock: Callback::noop(),
            pass_stock: Callback::noop(),
            simulate: Callback::noop(),
            root,
            tell_course: None,
        }
    }
}

/// Runs each list of effects once, after the render.
#[hook]
pub fn use_effects(pending: &Pending, shell: Shell) {
    use_effect_with(pending.clone(), move |p| {
        for at in 0..p.list.len() {
            run(&p.list, at, &shell);
        }
    });
}

/// Texts longer than this (bytes) are saved after a pause of `SAVE_PAUSE_MS`.
const BIG_SAVE: usize = 256 * 1024;
const SAVE_PAUSE_MS: u64 = 1000;

thread_local! {
    /// The big text waiting to be saved: the list of effects it is in and its place there (a
    /// copy of the text would cost milliseconds a keystroke).
    static LATER: std::cell::RefCell<Option<(Rc<[Effect]>, usize)>> = const { std::cell::RefCell::new(None) };
}

/// The key and text of a save effect.
fn save_of(effect: Option<&Effect>) -> Option<(&'static str, &str)> {
    match effect {
        Some(Effect::Save { key, value }) => Some((key, value)),
        _ => None,
    }
}

/// Runs the effect at `at` of `list`.
fn run(list: &Rc<[Effect]>, at: usize, shell: &Shell) {
    let Some(effect) = list.get(at) else { return };
    let root = || shell.root.cast::<web_sys::Element>();
    match effect {
        // A big program is written once typing pauses (megabytes a keystroke would cost more
        // than the keystroke); the latest text wins.
        Effect::Save { value, .. } if value.len() > BIG_SAVE => {
            let first = LATER.with(|l| l.borrow_mut().replace((list.clone(), at)).is_none());
            if first {
                let notice = shell.notice.clone();
                yew::platform::spawn_local(async move {
                    yew::platform::time::sleep(std::time::Duration::from_millis(SAVE_PAUSE_MS)).await;
                    let later = LATER.with(|l| l.borrow_mut().take());
                    if let Some((key, value)) = later.as_ref().and_then(|(list, at)| save_of(list.get(*at)))
                        && let Err(message) = browser::save(key, value)
                    {
                        notice.emit(message);
                    }
                });
            }
        }
        Effect::Save { key, value } => {
            LATER.with(|l| {
                l.borrow_mut().take_if(|(list, at)| save_of(list.get(*at)).is_some_and(|(k, _)| k == *key))
            });
            if let Err(message) = browser::save(key, value) {
                shell.notice.emit(message);
            }
        }
        Effect::Download { name, text } => {
            let bytes = schwenkbar_core::text::encode_latin1(text);
            shell.notice.emit(match browser::download(name, &bytes) {
                Ok(()) => Text::new(
                    "Programm wird als .h-Datei heruntergeladen",
                    "The program is downloaded as a .h file",
                ),
                Err(message) => message,
            });
        }
        Effect::SaveFile { name, text } => {
            if let Err(message) = browser::download(name, text.as_bytes()) {
                shell.notice.emit(message);
            }
        }
        Effect::OpenPage { url } => browser::open_page(url),
        Effect::Share { fragment } => {
            let notice = shell.notice.clone();
            let fragment = fragment.clone();
            yew::platform::spawn_local(async move {
                let copied = match browser::share_url(&fragment) {
                    Some(url) => browser::copy_to_clipboard(&url).await.is_ok(),
                    None => false,
                };
                notice.emit(if copied {
                    Text::new(
                        "Link in die Zwischenablage kopiert: einfügen und weitergeben",
                        "Link copied to the clipboard: paste it and pass it on",
                    )
                } else {
                    match browser::set_fragment(&fragment) {
                        Ok(()) => Text::new(
                            "Link steht in der Adresszeile: kopieren und weitergeben",
                            "The link is in the address bar: copy and pass it on",
                        ),
                        Err(message) => message,
                    }
                });
            });
        }
        Effect::PickFile => {
            if let Some(root) = root() {
                browser::pick_file(&root);
            }
        }
        Effect::FocusEditor => {
            if let Some(root) = root() {
                browser::focus(&root, "textarea.program-text");
            }
        }
        Effect::ConsumeFragment => browser::consume_fragment(),
        Effect::Tick { step, ms } => {
            let (tick, step, ms) = (shell.tick.clone(), *step, *ms);
            yew::platform::spawn_local(async move {
                yew::platform::time::sleep(std::time::Duration::from_millis(ms)).await;
                tick.emit(step);
            });
        }
        Effect::BuildStock => {
            let build = shell.build_stock.clone();
            yew::platform::spawn_local(async move {
                // Long enough for the browser to paint the run's first screen.
                yew::platform::time::sleep(std::time::Duration::from_millis(50)).await;
                build.emit(());
            });
        }
        Effect::PassStock => {
            let pass = shell.pass_stock.clone();
            yew::platform::spawn_local(async move {
                // A frame: the browser paints (and the view cuts its own share) between two.
                yew::platform::time::sleep(std::time::Duration::from_millis(16)).await;
                pass.emit(());
            });
        }
        Effect::Simulate => {
            let simulate = shell.simulate.clone();
            yew::platform::spawn_local(async move {
                browser::deferred_code().await;
                simulate.emit(());
            });
        }
        Effect::TellCourse(block) => {
            if let Some(tell) = &shell.tell_course {
                tell.emit(block.clone());
            }
        }
    }
}
