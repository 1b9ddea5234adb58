//! The macro behind the settings' enums: each value's name on the command line and in
//! settings files, parsed back with an error that lists the names on offer.

/// An enum of settings values with the names the CLI and settings files use: `ALL`, `name()`,
/// `FromStr` (an error lists the names on offer) and serde by the same names.
macro_rules! named_enum {
    (
        $(#[$meta:meta])*
        pub enum $name:ident ($what:literal) {
            $($(#[$variant_meta:meta])* $variant:ident = $text:literal,)+
        }
    ) => {
        $(#[$meta])*
        #[derive(
            Clone,
            Copy,
            Debug,
            Default,
            PartialEq,
            Eq,
            Hash,
            serde::Serialize,
            serde::Deserialize,
        )]
        pub enum $name {
            $($(#[$variant_meta])* #[serde(rename = $text)] $variant,)+
        }

        impl $name {
            /// Every value, in the order help texts list them.
            pub const ALL: [$name; [$($text),+].len()] = [$($name::$variant),+];

            /// The name used on the command line and in settings files.
            ///
            #[doc = concat!("```\nuse aokit::", stringify!($name), ";\n")]
            /// // Every value reads back from its name, as `--set` and settings files give it.
            #[doc = concat!("for value in ", stringify!($name), "::ALL {")]
            #[doc = concat!("    assert_eq!(value.name().parse::<", stringify!($name), ">(), Ok(value));")]
            /// }
            /// ```
            pub fn name(self) -> &'static str {
                match self {
                    $($name::$variant => $text,)+
                }
            }
        }

        impl $crate::settings::Field for $name {
            const NAMES: &'static [&'static str] = &[$($text),+];
            fn to_value(self) -> $crate::settings::SettingValue {
                $crate::settings::SettingValue::Choice(self.name())
            }
            fn from_value(value: $crate::settings::SettingValue) -> Result<Self, String> {
                match value {
                    $crate::settings::SettingValue::Choice(name) => name.parse(),
                    other => Err(format!("expected a {} name, not {other}", $what)),
                }
            }
        }

        impl std::str::FromStr for $name {
            type Err = String;
            fn from_str(s: &str) -> Result<Self, String> {
                $crate::settings::find_by_name(&$name::ALL, $name::name, $what, s)
            }
        }
    };
}
pub(crate) use named_enum;

/// The member of `all` called `wanted`, or an error listing the names on offer.
pub(crate) fn find_by_name<T: Copy>(
    all: &[T],
    name: fn(T) -> &'static str,
    what: &str,
    wanted: &str,
) -> Result<T, String> {
    all.iter()
        .copied()
        .find(|&t| name(t) == wanted)
        .ok_or_else(|| {
            let known: Vec<&str> = all.iter().map(|&t| name(t)).collect();
            format!("unknown {what} `{wanted}` (known: {})", known.join(", "))
        })
}
